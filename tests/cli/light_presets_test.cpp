// Light presets (docs/lights.md): flames (sphere lights with a blackbody spectrum), the camera flash and
// the LED work light render; bad fields are refused naming the scene file and the field.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/bad_scene.h"
#include "cli/render_probe.h"

namespace ochre::test::light_presets_test {
namespace {

// A grey wall at z = 0 facing +z, seen from z = 4, lit by `light` only.
std::string wall_lit_by(const std::string& light) {
  return R"({"camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov": 40}, "film": {"resolution": [16, 16]},
             "integrator": {"spp": 16}, "materials": {"grey": {"type": "lambert", "color": 0.5}},
             "lights": [)" +
         light + R"(], "shapes": [{"type": "plane", "size": [8, 8], "material": "grey"}]})";
}

// A flame of intensity I at distance d (3 m: the 4 central pixels are within 0.5 % of the perpendicular) in
// front of a Lambertian wall of albedo a: radiance a I / (pi d^2) at the foot of the perpendicular, as for a
// point light (the sphere's intensity is the preset's).
TEST(LightPresets, FlameLightsTheWallLikeItsIntensity) {
  const LuminanceImage image =
      render_luminance(wall_lit_by(R"({"type": "flame", "preset": "grease_lamp", "position": [0, 0, 3]})"));
  const double expected = 0.5 * 1.0 / (M_PI * 9.0);  // grease lamp: 1 cd at 3 m
  EXPECT_NEAR(image.mean(7, 7, 9, 9) / expected, 1.0, 0.03);
  const LuminanceImage scaled = render_luminance(
      wall_lit_by(R"({"type": "flame", "preset": "grease_lamp", "position": [0, 0, 3], "scale": 2})"));
  EXPECT_NEAR(scaled.mean(7, 7, 9, 9) / image.mean(7, 7, 9, 9), 2.0, 1e-3);
}

TEST(LightPresets, CameraFlashAndLedLight) {
  const LuminanceImage flash = render_luminance(wall_lit_by(R"({"type": "camera_flash", "scale": 0.01})"));
  EXPECT_GT(flash.mean(6, 6, 10, 10), 0.0);
  const LuminanceImage led = render_luminance(wall_lit_by(
      R"({"type": "spot", "preset": "led_work_light", "position": [0, 0, 2], "target": [0, 0, 0]})"));
  // 318 cd on the axis at 2 m on albedo 0.5: 0.5 x 318 / (4 pi).
  EXPECT_NEAR(led.mean(7, 7, 9, 9) / (0.5 * 318.0 / (4.0 * M_PI)), 1.0, 0.03);
}

TEST(LightPresets, BadFieldsAreNamed) {
  const BadCase cases[] = {
      {"unknown flame preset",
       wall_lit_by(R"({"type": "flame", "preset": "candle", "position": [0, 0, 1]})"),
       {"lights[0].preset", "unknown flame preset 'candle'", "torch"}},
      {"flame without preset",
       wall_lit_by(R"({"type": "flame", "position": [0, 0, 1]})"),
       {"lights[0].preset"}},
      {"flame without position",
       wall_lit_by(R"({"type": "flame", "preset": "torch"})"),
       {"lights[0].position"}},
      {"zero radius",
       wall_lit_by(R"({"type": "flame", "preset": "torch", "position": [0, 0, 1], "radius": 0})"),
       {"lights[0].radius"}},
      {"cold flame",
       wall_lit_by(R"({"type": "flame", "preset": "torch", "position": [0, 0, 1], "cct": 100})"),
       {"lights[0].cct"}},
      {"negative scale",
       wall_lit_by(R"({"type": "flame", "preset": "torch", "position": [0, 0, 1], "scale": -1})"),
       {"lights[0].scale"}},
      {"negative flicker",
       wall_lit_by(
           R"({"type": "flame", "preset": "torch", "position": [0, 0, 1], "flicker": {"relative_std": -0.1}})"),
       {"lights[0].flicker.relative_std"}},
      {"zero frequency",
       wall_lit_by(
           R"({"type": "flame", "preset": "torch", "position": [0, 0, 1], "flicker": {"frequency": 0}})"),
       {"lights[0].flicker.frequency"}},
      {"unknown flicker key",
       wall_lit_by(R"({"type": "flame", "preset": "torch", "position": [0, 0, 1], "flicker": {"depth": 1}})"),
       {"lights[0].flicker", "depth"}},
      {"unknown spot preset",
       wall_lit_by(R"({"type": "spot", "preset": "sun", "position": [0, 0, 2], "target": [0, 0, 0]})"),
       {"lights[0].preset", "unknown spot preset 'sun'", "led_work_light"}},
      {"preset and intensity",
       wall_lit_by(
           R"({"type": "spot", "preset": "flash", "intensity": 1, "position": [0, 0, 2], "target": [0, 0, 0]})"),
       {"lights[0].intensity", "preset sets the intensity"}},
      {"scale without preset",
       wall_lit_by(
           R"({"type": "spot", "intensity": 1, "scale": 2, "position": [0, 0, 2], "target": [0, 0, 0]})"),
       {"lights[0].scale"}},
      {"flash offset type", wall_lit_by(R"({"type": "camera_flash", "offset": "up"})"), {"lights[0].offset"}},
      {"flash unknown key",
       wall_lit_by(R"({"type": "camera_flash", "target": [0, 0, 0]})"),
       {"lights[0]", "target"}},
  };
  for (const BadCase& c : cases) expect_rejected(c);
}

}  // namespace
}  // namespace ochre::test::light_presets_test
