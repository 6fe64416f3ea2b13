#include "renderer/scene/polarization_mode.h"

namespace ochre {

const char* polarization_mode_name(PolarizationMode mode) {
  switch (mode) {
    case PolarizationMode::kOff:
      return "off";
    case PolarizationMode::kIntensity:
      return "intensity";
    case PolarizationMode::kStokes:
      return "stokes";
  }
  return "off";
}

PolarizationChoice choose_polarization_mode(PolarizationSetting requested, bool scene_polarizes,
                                            bool stokes_output_requested) {
  switch (requested) {
    case PolarizationSetting::kOff:
      return {PolarizationMode::kOff, "requested"};
    case PolarizationSetting::kIntensity:
      return {PolarizationMode::kIntensity, "requested"};
    case PolarizationSetting::kStokes:
      return {PolarizationMode::kStokes, "requested"};
    case PolarizationSetting::kAuto:
      break;
  }
  if (stokes_output_requested) return {PolarizationMode::kStokes, "auto: a Stokes output is requested"};
  if (scene_polarizes) return {PolarizationMode::kIntensity, "auto: a material or a filter polarizes"};
  return {PolarizationMode::kOff, "auto: no material or filter polarizes"};
}

}  // namespace ochre
