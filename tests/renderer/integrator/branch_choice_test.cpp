// integrator.branches "auto" (renderer/integrator/branch_choice.h): a pilot chooses how many continuations a
// camera sample gets, from the scene and the settings only; spp then counts paths per pixel.
#include "renderer/integrator/branch_choice.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::branch_choice_test {
namespace {

LoadedScene cornell_box(int size, uint32_t spp) {
  SceneOverrides o;
  o.width = size;
  o.height = size;
  o.spp = spp;
  return load_scene(test::source_dir() / "scenes" / "cornell-box" / "cornell-box.json", o);
}

void print(const char* what, const BranchChoice& c) {
  std::printf("%s: %d branches, piloted %d, shared variance %.4f, costs %.3f / %.3f, optimum %.3f, %s\n",
              what, c.branches, c.piloted, c.shared_variance, c.shared_cost, c.branch_cost, c.optimum,
              c.reason.c_str());
}

// The Cornell box's noise is in its indirect light (the first vertex's light sample from one area light is
// nearly noise-free): the pilot branches, as hand-tuning found (2 on the matched box of the benchmarks).
TEST(BranchChoice, BranchesWhereTheNoiseIsIndirect) {
  const LoadedScene scene = cornell_box(128, 64);
  EXPECT_EQ(scene.job.settings.branches, RenderSettings::kAutoBranches);  // the default
  const BranchChoice c = choose_branches(*scene.scene, scene.job);
  print("cornell box 128x128, 64 spp", c);
  EXPECT_TRUE(c.piloted);
  EXPECT_GE(c.branches, 2);
  EXPECT_LE(c.branches, 8);
  EXPECT_LT(c.shared_variance, 0.25);
  // A first vertex costs one ray, a light sample and the camera sample's own work; a continuation the rest of
  // the path (max depth 8, roulette from 5).
  EXPECT_NEAR(c.shared_cost, 1.0 + 0.25 + 0.5, 0.1);
  EXPECT_GT(c.branch_cost, 2.0);
  EXPECT_GT(c.predicted_gain, 1.0);
}

// Direct light only (max depth 1) from a small sphere light: the noise is the first vertex's light sample,
// which every branch would share, and a continuation adds only the BSDF ray's MIS-weighted hits of the light.
TEST(BranchChoice, KeepsOnePathWhereTheNoiseIsAtTheFirstVertex) {
  LoadedScene scene = cornell_box(128, 64);
  scene.job.settings.max_depth = 1;
  const BranchChoice c = choose_branches(*scene.scene, scene.job);
  print("cornell box, direct light only", c);
  EXPECT_TRUE(c.piloted);
  EXPECT_EQ(c.branches, 1);
  EXPECT_GT(c.shared_variance, 0.5);
}

// The choice is a function of the scene and the settings: not of the seed or the thread count.
TEST(BranchChoice, SameChoiceForAnySeedAndThreadCount) {
  LoadedScene scene = cornell_box(128, 64);
  scene.job.settings.threads = 1;
  const BranchChoice one = choose_branches(*scene.scene, scene.job);
  scene.job.settings.threads = 2;
  scene.job.settings.seed = 12345;
  const BranchChoice two = choose_branches(*scene.scene, scene.job);
  EXPECT_EQ(one.branches, two.branches);
  EXPECT_EQ(one.rr_depth, two.rr_depth);
  EXPECT_EQ(one.shared_variance, two.shared_variance);  // the same sums, in the same order
  EXPECT_EQ(one.shared_cost, two.shared_cost);
  EXPECT_EQ(one.branch_cost, two.branch_cost);
  EXPECT_EQ(one.optimum, two.optimum);
}

// k divides spp and leaves 4 camera samples (32 in a noise-threshold render: a decision before the maximum);
// small renders keep one path.
TEST(BranchChoice, CountsThatDivideTheSamples) {
  LoadedScene scene = cornell_box(128, 64);
  for (const uint32_t spp : {6u, 7u, 8u, 12u, 24u, 64u}) {
    scene.job.settings.spp = spp;
    const BranchChoice c = choose_branches(*scene.scene, scene.job);
    EXPECT_EQ(spp % c.branches, 0u) << spp;
    EXPECT_GE(spp / c.branches, 4u) << spp;
    if (spp < 8) {
      EXPECT_EQ(c.branches, 1) << spp;
    }
  }
  scene.job.settings.noise_threshold = 0.01;
  for (const uint32_t spp : {64u, 128u, 256u}) {
    scene.job.settings.spp = spp;
    const BranchChoice c = choose_branches(*scene.scene, scene.job);
    EXPECT_TRUE(c.piloted) << spp;
    EXPECT_EQ(spp % c.branches, 0u) << spp;
    EXPECT_GE(spp / c.branches, 32u) << spp;  // the first decision, at 16, comes before the maximum
  }
  scene.job.settings.spp = 256;
  EXPECT_GT(choose_branches(*scene.scene, scene.job).branches, 1);  // as without a threshold (above)
  scene.job.settings.spp = 32;
  scene.job.settings.max_depth = 3;  // one branch at most and no earlier start to weigh: no pilot
  EXPECT_FALSE(choose_branches(*scene.scene, scene.job).piloted);
  scene.job.settings.max_depth = 8;
  const LoadedScene small = cornell_box(16, 64);  // 16 k paths: less than 10 pilots
  EXPECT_FALSE(choose_branches(*small.scene, small.job).piloted);
}

// rr_depth auto: the pilot weighs roulette from depth 3 against 5 where paths reach them; a number is kept.
TEST(BranchChoice, RouletteStartIsChosenOrKept) {
  LoadedScene scene = cornell_box(128, 64);
  EXPECT_EQ(scene.job.settings.rr_depth, RenderSettings::kAutoRoulette);  // the default
  const BranchChoice automatic = choose_branches(*scene.scene, scene.job);
  print("cornell box, roulette auto", automatic);
  EXPECT_TRUE(automatic.piloted);
  EXPECT_TRUE(automatic.rr_depth == 3 || automatic.rr_depth == 5) << automatic.rr_depth;
  EXPECT_GE(automatic.predicted_gain, 1.0);
  const RenderJob resolved = resolve_branches(*scene.scene, scene.job);
  EXPECT_EQ(resolved.settings.rr_depth, automatic.rr_depth);
  EXPECT_TRUE(resolved.settings.roulette_chosen);
  // Paths of at most 3 bounces: only the default start is a candidate.
  scene.job.settings.max_depth = 3;
  EXPECT_EQ(choose_branches(*scene.scene, scene.job).rr_depth, RenderSettings::kDefaultRouletteDepth);
  scene.job.settings.max_depth = 8;
  scene.job.settings.rr_depth = 7;
  const RenderJob kept = resolve_branches(*scene.scene, scene.job);
  EXPECT_EQ(kept.settings.rr_depth, 7);
  EXPECT_FALSE(kept.settings.roulette_chosen);
  EXPECT_TRUE(kept.settings.branches_chosen);
}

// A point light and a sky over a Lambert plane (as tests/cli/light_selection_test.cpp), 64x64, 256 spp: one
// light chosen per vertex, the choice is most of the noise (the point light's term is exact once chosen).
LoadedScene point_light_and_sky(const char* light_selection) {
  const nlohmann::json scene = nlohmann::json::parse(fmt::format(R"({{
      "camera": {{"type": "orthographic", "size": 4, "eye": [0, 0, 5], "target": [0, 0, 0]}},
      "film": {{"resolution": [64, 64]}},
      "integrator": {{"spp": 256, "max_depth": 2, "light_selection": "{}"}},
      "materials": {{"m": {{"type": "lambert", "color": 0.5}}}},
      "lights": [{{"type": "point", "position": [0, 0, 1], "intensity": 10}},
                 {{"type": "environment", "radiance": 0.2}}],
      "shapes": [{{"type": "plane", "size": [100, 100], "material": "m"}}]
    }})",
                                                                 light_selection));
  return load_scene_json(scene, "<point light and sky>", test::scratch_dir() / "scene.json");
}

// light_selection auto: with 2-8 lights the pilot weighs sampling every light against choosing one; it
// samples both here, where choosing is the noise. A selection that is set is kept; one light has no choice.
TEST(BranchChoice, LightSamplingIsChosenOrKept) {
  const LoadedScene scene = point_light_and_sky("auto");
  const BranchChoice c = choose_branches(*scene.scene, scene.job);
  print("point light and sky, light selection auto", c);
  EXPECT_TRUE(c.piloted);
  EXPECT_EQ(c.light_selection, LightSelection::kAll);
  EXPECT_GT(c.predicted_gain, 1.5);
  EXPECT_NE(c.reason.find("all 2 lights sampled at each vertex"), std::string::npos) << c.reason;
  const RenderJob resolved = resolve_branches(*scene.scene, scene.job);
  EXPECT_EQ(resolved.settings.light_selection, LightSelection::kAll);
  EXPECT_TRUE(resolved.settings.light_selection_chosen);

  const LoadedScene local = point_light_and_sky("local");
  EXPECT_EQ(choose_branches(*local.scene, local.job).light_selection, LightSelection::kLocal);
  const RenderJob kept = resolve_branches(*local.scene, local.job);
  EXPECT_EQ(kept.settings.light_selection, LightSelection::kLocal);
  EXPECT_FALSE(kept.settings.light_selection_chosen);

  const LoadedScene box = cornell_box(128, 64);  // one light: nothing to choose
  EXPECT_EQ(box.job.settings.light_selection, LightSelection::kAuto);
  EXPECT_EQ(choose_branches(*box.scene, box.job).light_selection, LightSelection::kLocal);
}

// resolve_branches turns paths into camera samples; an explicit count is kept with its meaning.
TEST(BranchChoice, ResolvedJobCountsCameraSamples) {
  LoadedScene scene = cornell_box(128, 64);
  BranchChoice c;
  const RenderJob resolved = resolve_branches(*scene.scene, scene.job, &c);
  EXPECT_TRUE(resolved.settings.branches_chosen);
  EXPECT_EQ(resolved.settings.branches, c.branches);
  EXPECT_EQ(resolved.settings.spp * static_cast<uint32_t>(c.branches), 64u);
  scene.job.settings.sample_begin = 1;  // not a whole camera sample of c.branches > 1: k must divide it
  EXPECT_EQ(resolve_branches(*scene.scene, scene.job).settings.branches, 1);
  scene.job.settings.sample_begin = 0;
  scene.job.settings.branches = 3;
  const RenderJob fixed = resolve_branches(*scene.scene, scene.job);
  EXPECT_EQ(fixed.settings.branches, 3);
  EXPECT_EQ(fixed.settings.spp, 64u);
  EXPECT_FALSE(fixed.settings.branches_chosen);
  // render_range needs the count: its range counts camera samples.
  scene.job.settings.branches = RenderSettings::kAutoBranches;
  Film film(128, 128);
  EXPECT_THROW(render_range(*scene.scene, scene.job, film, {0, 0, 128, 128}, {0, 1}), std::invalid_argument);
}

// An auto render is the render of its chosen count: the same bits as the explicit job, unbiased against a
// plain path-traced render of the same number of paths (the mean of the image within its noise).
TEST(BranchChoice, AutoRenderIsTheChosenCountsRender) {
  const LoadedScene scene = cornell_box(128, 48);
  BranchChoice c;
  const RenderJob resolved = resolve_branches(*scene.scene, scene.job, &c);
  ASSERT_GT(c.branches, 1);
  Film automatic(128, 128), chosen(128, 128), plain(128, 128);
  render(*scene.scene, scene.job, automatic);
  render(*scene.scene, resolved, chosen);
  RenderJob one = scene.job;
  one.settings.branches = 1;
  render(*scene.scene, one, plain);
  double a = 0, b = 0;
  bool same = true;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      same = same && automatic.mean(x, y) == chosen.mean(x, y);
      a += automatic.mean(x, y).y;
      b += plain.mean(x, y).y;
    }
  EXPECT_TRUE(same);
  std::printf("mean Y: auto (%d branches) %.5f, one branch %.5f\n", c.branches, a / (128 * 128),
              b / (128 * 128));
  EXPECT_NEAR(a / b, 1.0, 0.01);
}

}  // namespace
}  // namespace ochre::branch_choice_test
