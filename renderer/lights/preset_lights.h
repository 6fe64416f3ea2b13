#pragma once
// Scene lights built from the presets of renderer/lights/light_presets.h (docs/lights.md):
//   {"type": "flame", "preset": "torch", "position": [x, y, z], "radius", "cct", "intensity", "scale",
//    "flicker": {"relative_std", "frequency", "cct_std", "position_std"}}
//   {"type": "camera_flash", "offset": [right, up, forward], "preset": "flash", "scale", "cone_angle",
//    "falloff_start"}   a spot light beside the lens, aimed along the camera's view
//   {"type": "spot", "preset": "led_work_light", "scale", ...}   a spot light with the preset's spectrum,
//    intensity and cone (the spot's own keys override the cone)
// Errors name the file and the field (InputError).

#include <memory>

#include "renderer/camera/camera.h"
#include "renderer/json/json_fields.h"
#include "renderer/lights/flame_light.h"
#include "renderer/lights/spot_light.h"

namespace ochre {

// A flame: its sphere light (returned, for Scene::lights) and its FlameLight record (added to scene.flames
// once the caller has stored the light).
struct LoadedFlame {
  std::unique_ptr<SphereLight> light;
  FlameLight flame;
};
LoadedFlame load_flame(const JsonFields& f);

std::unique_ptr<SpotLight> load_camera_flash(const JsonFields& f, const Camera& camera);

// The intensity (on the axis) of a spot light with `"preset"`, and the preset's cone angles unless the
// light gives its own.
struct SpotPresetValues {
  SpectrumPtr intensity;
  double cone_angle, falloff_start;
};
SpotPresetValues spot_preset_values(const JsonFields& f);

}  // namespace ochre
