#include "renderer/scene/polarization_mode.h"

#include <fmt/format.h>

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

PolarizationChoice choose_polarization_mode(PolarizationSetting requested, const PolarizationNeeds& needs,
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
  if (needs.filters) return {PolarizationMode::kIntensity, "auto: a polarizer filter"};
  if (!needs.materials) return {PolarizationMode::kOff, "auto: no material or filter polarizes"};
  const PolarizationSignificance& s = needs.significance;
  if (s.delta_lobes)
    return {PolarizationMode::kIntensity, "auto: a material polarizes (a mirror or glass lobe)"};
  const std::string figures = fmt::format("diattenuation {:.2g} x polarizance {:.2g} = {:.2g}",
                                          s.diattenuation, s.polarizance, s.bound());
  if (s.bound() >= kPolarizationSignificant)
    return {PolarizationMode::kIntensity, "auto: a material polarizes (" + figures + ")"};
  return {PolarizationMode::kOff, fmt::format("auto: the materials polarize too little to change intensities "
                                              "({} < {:g})",
                                              figures, kPolarizationSignificant)};
}

}  // namespace ochre
