// Physics of whole renders through the CLI: white furnace, analytic direct lighting.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "cli/render_probe.h"

namespace ochre::test {
namespace {

// One Lambert sphere (radius 1) filling the centre of an orthographic view, in a constant
// environment of radiance 1 (equal-energy spectrum: luminance 1).
std::string furnace_scene(double albedo) {
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 3, "eye": [0, 0, 10], "target": [0, 0, 0]}},
    "film": {{"resolution": [48, 48]}},
    "integrator": {{"spp": 256, "max_depth": 100, "rr_depth": 100}},
    "materials": {{"m": {{"type": "lambert", "color": {}}}}},
    "lights": [{{"type": "environment", "radiance": 1.0}}],
    "shapes": [{{"type": "sphere", "radius": 1, "subdivisions": 256, "material": "m"}}]
  }})",
                     albedo);
}

TEST(WhiteFurnace, LambertSpheresRenderAlbedoTimesL) {
  for (double albedo : {1.0, 0.5}) {
    const LuminanceImage img = render_luminance(furnace_scene(albedo));
    ASSERT_EQ(img.width, 48);
    // The central 16x16 pixels lie inside the sphere's silhouette (radius 16 px).
    const double sphere = img.mean(16, 16, 32, 32);
    const double background = img.mean(0, 0, 4, 4);
    std::printf("furnace albedo %.2f: sphere Y = %.5f, background Y = %.5f\n", albedo, sphere, background);
    EXPECT_NEAR(background, 1.0, 0.005);
    EXPECT_NEAR(sphere, albedo, 0.005 * albedo);
  }
}

// A point light of intensity I at height h over a Lambert plane of albedo rho, seen from
// above with an orthographic camera: L = rho / pi * I cos(theta) / r^2 at every pixel.
TEST(AnalyticDirectLighting, PointLightOverLambertPlane) {
  const double rho = 0.5, I = 10.0, h = 1.0, view = 4.0;
  const int res = 32;
  const LuminanceImage img = render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": {}, "eye": [0, 0, 5], "target": [0, 0, 0]}},
    "film": {{"resolution": [{}, {}]}},
    "integrator": {{"spp": 1024, "max_depth": 1}},
    "materials": {{"m": {{"type": "lambert", "color": {}}}}},
    "lights": [{{"type": "point", "position": [0, 0, {}], "intensity": {}}}],
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "m"}}]
  }})",
                                                          view, res, res, rho, h, I));
  ASSERT_EQ(img.width, res);
  double worst = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      // The pixel is a box filter: average the analytic radiance over its footprint (8x8 points;
      // x right, y up in the image).
      double expected = 0.0;
      for (int sj = 0; sj < 8; ++sj)
        for (int si = 0; si < 8; ++si) {
          const double x = (i + (si + 0.5) / 8) / res * view - view / 2;
          const double y = view / 2 - (j + (sj + 0.5) / 8) / res * view;
          const double r2 = x * x + y * y + h * h;
          expected += rho / M_PI * I * (h / std::sqrt(r2)) / r2 / 64.0;
        }
      worst = std::max(worst, std::fabs(img.at(i, j) / expected - 1.0));
    }
  std::printf("point light over Lambert plane: worst per-pixel relative error %.4f\n", worst);
  EXPECT_LT(worst, 0.01);
}

// A constant environment L over a Lambert plane seen straight down: every pixel is rho L.
TEST(AnalyticDirectLighting, ConstantEnvironmentOverPlane) {
  const LuminanceImage img = render_luminance(R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [16, 16]},
    "integrator": {"spp": 256, "max_depth": 1},
    "materials": {"m": {"type": "lambert", "color": 0.3}},
    "lights": [{"type": "environment", "radiance": 2.0}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "m"}]
  })");
  ASSERT_EQ(img.width, 16);
  const double mean = img.mean(0, 0, 16, 16);
  std::printf("constant environment over plane: mean Y = %.5f (expected 0.6)\n", mean);
  EXPECT_NEAR(mean, 0.6, 0.006);
}

}  // namespace
}  // namespace ochre::test
