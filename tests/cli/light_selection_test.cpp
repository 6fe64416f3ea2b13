// Choosing the light for next-event estimation (docs/architecture.md, 'Choosing the light'): by power, at
// each shading point from the lights' importance there, or every light at every vertex. All are unbiased: the
// same closed-form image.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/bad_scene.h"
#include "cli/point_light_and_sky.h"

namespace ochre::test::light_selection_test {
namespace {

// The point light and sky over a plane (cli/point_light_and_sky.h). The plane is large, so the sky's power
// (its flux through the scene's bounding sphere) dwarfs the point light's: chosen by power, the point light
// gets 0.3 % of the samples and the image is noisy, though right on average. With every light sampled the
// point light's delta term is exact at every sample: only the sky's own sampling is noise.
TEST(LightSelection, PointLightAndSkyAddUpWithEveryChoice) {
  const char* selections[3] = {"local", "power", "all"};
  double worst_of[3] = {};
  for (int k = 0; k < 3; ++k) {
    const char* selection = selections[k];
    const PointLightAndSky r = render_point_light_and_sky(
        fmt::format(R"("spp": 1024, "max_depth": 1, "light_selection": "{}")", selection));
    std::printf(
        "point light + sky, light selection %s: worst per-pixel relative error %.4f, mean %.5f (expected "
        "%.5f)\n",
        selection, r.worst, r.mean, r.expected_mean);
    EXPECT_NEAR(r.mean / r.expected_mean, 1.0, 0.01) << selection;
    worst_of[k] = r.worst;
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
