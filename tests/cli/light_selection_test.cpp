// Choosing the light for next-event estimation (docs/architecture.md, 'Choosing the light'): by power, at
// each shading point from the lights' importance there, or every light at every vertex. All are unbiased: the
// same closed-form image.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "cli/bad_scene.h"
#include "cli/render_probe.h"

namespace ochre::test::light_selection_test {
namespace {

// A point light (intensity I at height h) and a constant environment (radiance Le) over a Lambert plane of
// albedo rho, seen from above: L = rho / pi * I cos / r^2 + rho Le at every point. The plane is large, so the
// sky's power (its flux through the scene's bounding sphere) dwarfs the point light's: chosen by power, the
// point light gets 0.3 % of the samples and the image is noisy, though right on average. With every light
// sampled the point light's delta term is exact at every sample: only the sky's own sampling is noise.
TEST(LightSelection, PointLightAndSkyAddUpWithEveryChoice) {
  const double rho = 0.5, I = 10.0, h = 1.0, Le = 0.2, view = 4.0;
  const int res = 16;
  const char* selections[3] = {"local", "power", "all"};
  double worst_of[3] = {};
  for (int k = 0; k < 3; ++k) {
    const char* selection = selections[k];
    const LuminanceImage img = render_luminance(fmt::format(R"({{
      "camera": {{"type": "orthographic", "size": {}, "eye": [0, 0, 5], "target": [0, 0, 0]}},
      "film": {{"resolution": [{}, {}]}},
      "integrator": {{"spp": 1024, "max_depth": 1, "light_selection": "{}"}},
      "materials": {{"m": {{"type": "lambert", "color": {}}}}},
      "lights": [{{"type": "point", "position": [0, 0, {}], "intensity": {}}},
                 {{"type": "environment", "radiance": {}}}],
      "shapes": [{{"type": "plane", "size": [100, 100], "material": "m"}}]
    }})",
                                                            view, res, res, selection, rho, h, I, Le));
    ASSERT_EQ(img.width, res);
    double worst = 0.0, sum = 0.0, sum_expected = 0.0;
    for (int j = 0; j < res; ++j)
      for (int i = 0; i < res; ++i) {
        double expected = 0.0;  // averaged over the pixel (box filter), 8 x 8 points
        for (int sj = 0; sj < 8; ++sj)
          for (int si = 0; si < 8; ++si) {
            const double x = (i + (si + 0.5) / 8) / res * view - view / 2;
            const double y = view / 2 - (j + (sj + 0.5) / 8) / res * view;
            const double r2 = x * x + y * y + h * h;
            expected += (rho / M_PI * I * (h / std::sqrt(r2)) / r2 + rho * Le) / 64.0;
          }
        worst = std::max(worst, std::fabs(img.at(i, j) / expected - 1.0));
        sum += img.at(i, j);
        sum_expected += expected;
      }
    std::printf(
        "point light + sky, light selection %s: worst per-pixel relative error %.4f, mean %.5f (expected "
        "%.5f)\n",
        selection, worst, sum / (res * res), sum_expected / (res * res));
    EXPECT_NEAR(sum / sum_expected, 1.0, 0.01) << selection;
    worst_of[k] = worst;
  }
  EXPECT_LT(worst_of[0], 0.02);
  EXPECT_GT(worst_of[1], 5 * worst_of[0]);
  EXPECT_LT(worst_of[2], 0.2 * worst_of[0]);
}

TEST(LightSelection, UnknownChoiceIsRejected) {
  expect_rejected(
      {"light_selection",
       scene_with("/integrator/light_selection", R"("tree")"),
       {"integrator.light_selection", "unknown light selection 'tree'", "auto, local, power, all"}});
}

}  // namespace
}  // namespace ochre::test::light_selection_test
