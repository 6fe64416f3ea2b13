// The "camera_flash" light type (docs/lights.md, "Camera flash"): a spot light beside the lens, aimed along
// the camera's view, with the spectrum, intensity and cone of a spot preset.
#include <cmath>

#include "renderer/lights/light_type.h"
#include "renderer/lights/preset_lights.h"
#include "renderer/lights/spot_light.h"

namespace ochre {

namespace {

// The preset's spot light, aimed along `direction` from `position`.
std::unique_ptr<SpotLight> preset_spot(const JsonFields& f, const Vec3& position, const Vec3& direction) {
  const SpotPresetValues v = spot_preset_values(f);
  return std::make_unique<SpotLight>(position, direction, static_cast<float>(v.cone_angle),
                                     static_cast<float>(v.falloff_start), v.intensity);
}

BuiltLight build_camera_flash(const LightContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const CameraBasis& c = ctx.camera.basis();
  const Vec3 offset = f.vec3("offset");
  const Vec3 position = c.eye + c.right * offset.x + c.up * offset.y + c.forward * offset.z;
  if (!std::isfinite(length(position))) f.fail("offset", "puts the flash beyond single precision");
  std::unique_ptr<SpotLight> light;
  if (!f.has("preset")) {
    nlohmann::json with_preset = f.fields().json();
    with_preset["preset"] = "flash";
    const JsonFields defaulted(with_preset, f.fields().where());
    light = preset_spot(defaulted, position, c.forward);
  } else {
    light = preset_spot(f.fields(), position, c.forward);
  }
  light->polarizer_axis = parse_light_polarizer(f.fields());
  return {std::move(light), std::nullopt, "scale"};
}

}  // namespace

LightType camera_flash_light_type() {
  // Default offset: 10 cm above the lens, as a hot-shoe flash.
  return {
      "camera_flash",
      "a spot light beside the lens aimed along the view, with a spot preset's spectrum, intensity and cone",
      {vec3_field("offset", {0.0f, 0.1f, 0.0f},
                  "[right, up, forward] from the camera, in scene units (metres)"),
       string_field("preset", false, "the spot preset (default flash)"),
       number_field("scale", 1.0, 0.0, 1e30, "multiplies the preset's intensity"),
       computed_number_field("cone_angle", "the preset's", 0.0, 180.0, true,
                             "half-angle of the cone in degrees"),
       computed_number_field("falloff_start", "the preset's", 0.0, 180.0, true,
                             "half-angle where the falloff begins, at most `cone_angle`"),
       polarizer_field()},
      false,
      build_camera_flash};
}

}  // namespace ochre
