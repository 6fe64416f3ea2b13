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

PolarizationChoice choose_polarization_mode(const std::string& requested, bool scene_polarizes,
                                            bool stokes_output_requested) {
  if (requested == "off") return {PolarizationMode::kOff, "requested"};
  if (requested == "intensity") return {PolarizationMode::kIntensity, "requested"};
  if (requested == "stokes") return {PolarizationMode::kStokes, "requested"};
  if (stokes_output_requested) return {PolarizationMode::kStokes, "auto: a Stokes output is requested"};
  if (scene_polarizes) return {PolarizationMode::kIntensity, "auto: a material or a filter polarizes"};
  return {PolarizationMode::kOff, "auto: no material or filter polarizes"};
}

}  // namespace ochre
