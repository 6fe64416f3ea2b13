#pragma once
// Polarization modes (model only what a scene needs: docs/architecture.md, 'Design rules';
// docs/polarization.md, 'Modes'):
//   off       : scalar throughput; every element acts as a depolarizer (filters pass half);
//   intensity : the first row of the Mueller product (4 floats per wavelength); exact S0;
//   stokes    : the full Mueller product; S0..S3 at the sensor.
// auto picks off when nothing in the scene polarizes (no polarizing material, no polarizer filter),
// intensity when something does, stokes when a Stokes output is requested.

#include <string>

#include "renderer/scene/render_settings.h"

namespace ochre {

enum class PolarizationMode { kOff, kIntensity, kStokes };

const char* polarization_mode_name(PolarizationMode mode);

struct PolarizationChoice {
  PolarizationMode mode = PolarizationMode::kOff;
  std::string reason;  // e.g. "auto: no material or filter polarizes"
};

PolarizationChoice choose_polarization_mode(PolarizationSetting requested, bool scene_polarizes,
                                            bool stokes_output_requested);

}  // namespace ochre
