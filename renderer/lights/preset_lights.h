#pragma once
// Spot lights built from the presets of renderer/lights/light_presets.h (docs/lights.md), shared by the
// "spot" type with a "preset" (spot_light.cpp) and the "camera_flash" type (camera_flash.cpp):
//   {"type": "spot", "preset": "led_work_light", "scale", ...}   a spot light with the preset's spectrum,
//    intensity and cone (the spot's own keys override the cone)
// Flames, the other presets, are the "flame" type (flame_light.cpp). Errors name the file and the field
// (InputError).

#include "renderer/json/json_fields.h"
#include "spectra/spectrum.h"

namespace ochre {

// The intensity (on the axis) of a spot light with `"preset"`, and the preset's cone angles unless the
// light gives its own.
struct SpotPresetValues {
  SpectrumPtr intensity;
  double cone_angle, falloff_start;
};
SpotPresetValues spot_preset_values(const JsonFields& f);

}  // namespace ochre
