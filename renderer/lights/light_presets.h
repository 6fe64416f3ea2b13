#pragma once
// Named light presets (docs/lights.md): Palaeolithic flames after the experiments of Medina-Alcaide et
// al. 2021 ("The conquest of the dark spaces", PLOS ONE 16(5): e0250497), a white-LED work light and a
// camera flash. Each figure's origin (the paper, another source, or our estimate) is in docs/lights.md
// and beside the value in light_presets.cpp.

#include <string>
#include <string_view>
#include <vector>

#include "spectra/spectrum.h"

namespace ochre {

// The statistics of a flame's flicker (renderer/lights/flicker_process.h).
struct FlickerStats {
  float relative_std = 0.0f;  // standard deviation of the intensity / its mean
  float corner_hz = 1.0f;     // corner frequency of the intensity's spectrum (correlation time 1 / (2 pi f))
  float cct_std_k = 0.0f;     // standard deviation of the colour temperature, kelvin
  float position_std_m = 0.0f;  // standard deviation of the flame's position along each axis, metres
};

struct FlamePreset {
  std::string_view name;
  float cct_k;           // colour temperature of the blackbody spectrum
  float intensity_cd;    // mean luminous intensity in candela (a luminance-1 spectrum times this)
  float radius_m;        // radius of the emitting sphere
  float duration_min;    // how long it burns (documentation only: the renderer does not burn out)
  FlickerStats flicker;  // intensity, colour and position statistics
};

struct SpotPreset {
  std::string_view name;
  float intensity_cd;  // on the axis
  float cone_angle_deg, falloff_start_deg;
  SpectrumPtr (*spectrum)();  // normalised to luminance 1
};

// The preset of that name, or nullptr.
const FlamePreset* find_flame_preset(std::string_view name);
const SpotPreset* find_spot_preset(std::string_view name);
// "torch, torch_juniper, ..." for messages.
std::string flame_preset_names();
std::string spot_preset_names();

// A blackbody at `cct_k` normalised to luminance 1, times `intensity_cd`.
SpectrumPtr flame_spectrum(float cct_k, float intensity_cd);

}  // namespace ochre
