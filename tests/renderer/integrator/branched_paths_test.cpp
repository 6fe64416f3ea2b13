// Branched path tracing (integrator.branches): each camera sample continues from its first vertex along
// k paths, averaged. The estimate stays unbiased, deterministic for any thread count and split of the
// sample range, and its error per camera sample falls.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "renderer/integrator/render.h"
#include "renderer/integrator/same_pixels.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::branched_paths_test {
namespace {

constexpr int kSize = 32;

LoadedScene cornell_box(uint32_t spp, int branches, const char* file = "cornell-box/cornell-box.json") {
  SceneOverrides o;
  o.width = kSize;
  o.height = kSize;
  o.spp = spp;
  LoadedScene scene = load_scene(test::source_dir() / "scenes" / file, o);
  scene.job.settings.branches = branches;
  return scene;
}

Film render_film(const LoadedScene& scene) {
  Film film(scene.job.settings.width, scene.job.settings.height);
  render(*scene.scene, scene.job, film);
  return film;
}

double mean_y(const Film& film) {
  double sum = 0.0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) sum += film.mean(x, y).y;
  return sum / (film.width() * film.height());
}

// relMSE of Y against a reference film (epsilon as ochre-diff) over pixels [x0, x1) x [y0, y1), by default
// the whole film.
double relmse_y(const Film& film, const Film& ref, int x0 = 0, int y0 = 0, int x1 = -1, int y1 = -1) {
  if (x1 < 0) x1 = film.width();
  if (y1 < 0) y1 = film.height();
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const double a = film.mean(x, y).y, r = ref.mean(x, y).y;
      sum += (a - r) * (a - r) / (r * r + 1e-2);
    }
  return sum / ((x1 - x0) * (y1 - y0));
}

using test::same_pixels;

TEST(BranchedPaths, DeterministicForAnyThreadCountAndSplitOfTheSampleRange) {
  auto scene = cornell_box(6, 3);
  scene.job.settings.threads = 2;
  const Film whole = render_film(scene);
  scene.job.settings.threads = 1;
  EXPECT_TRUE(same_pixels(whole, render_film(scene)));

  Film part_a(kSize, kSize), part_b(kSize, kSize);
  scene.job.settings.spp = 2;
  render(*scene.scene, scene.job, part_a);
  scene.job.settings.sample_begin = 2;
  scene.job.settings.spp = 4;
  scene.job.settings.threads = 2;
  render(*scene.scene, scene.job, part_b);
  part_b.merge(part_a);
  EXPECT_TRUE(same_pixels(whole, part_b));

  // The branches draw numbers of their own: the image is not the unbranched one.
  scene.job.settings.sample_begin = 0;
  scene.job.settings.spp = 6;
  scene.job.settings.branches = 1;
  EXPECT_FALSE(same_pixels(whole, render_film(scene)));
}

// Same expected image, less error per camera sample: the Cornell box with 4 branches against 1, both against
// a converged unbranched render. The error compared is that of the back wall's middle, where it is all
// indirect light; across the whole 32x32 film the pixels' footprints (edges, the light) add the noise of
// the shared first vertex.
TEST(BranchedPaths, SameImageWithLessErrorPerCameraSample) {
  const Film ref = render_film(cornell_box(2048, 1));
  const Film one = render_film(cornell_box(8, 1));
  const Film four = render_film(cornell_box(8, 4));
  const Film four_long = render_film(cornell_box(512, 4));
  const double e1 = relmse_y(one, ref, 12, 12, 20, 20), e4 = relmse_y(four, ref, 12, 12, 20, 20);
  std::printf(
      "Cornell box 32x32, relMSE(Y) of the back wall's middle at 8 camera samples: 1 branch %.4g, "
      "4 branches %.4g; whole film %.4g and %.4g; mean Y %.5f (4 branches, 512 spp) vs %.5f (reference)\n",
      e1, e4, relmse_y(one, ref), relmse_y(four, ref), mean_y(four_long), mean_y(ref));
  // Four continuations per camera sample: well below the unbranched error, not below a quarter of it.
  EXPECT_LT(e4, 0.6 * e1);
  EXPECT_GT(e4, 0.2 * e1);
  // Unbiased: the image mean agrees with the reference within its noise (~0.1 % at these counts).
  EXPECT_NEAR(mean_y(four_long) / mean_y(ref), 1.0, 0.005);
  EXPECT_LT(relmse_y(four_long, ref), 2e-3);
}

// Polarized throughput (intensity mode), a smooth gold mirror and lights sampled through it: the vertex
// that the branches share keeps its lobes while theirs come and go.
TEST(BranchedPaths, PolarizedGoldMirrorBoxAgreesWithTheUnbranchedRender) {
  const Film ref = render_film(cornell_box(1024, 1, "benchmark/cbox-gold-back.json"));
  const Film branched = render_film(cornell_box(256, 4, "benchmark/cbox-gold-back.json"));
  std::printf("gold-back box 32x32: mean Y %.5f (4 branches, 256 spp) vs %.5f (1 branch, 1024 spp)\n",
              mean_y(branched), mean_y(ref));
  EXPECT_NEAR(mean_y(branched) / mean_y(ref), 1.0, 0.01);
  EXPECT_LT(relmse_y(branched, ref), 5e-3);
}

// A camera that sees only a smooth gold mirror, which shows it a Lambert wall: the branches leave the wall,
// the first vertex with a non-delta lobe, so the camera ray and the mirror bounce are traced once per camera
// sample. max_depth 2: each branch traces one ray from the wall and stops where it lands.
TEST(BranchedPaths, BranchesLeaveTheFirstNonDeltaVertex) {
  const nlohmann::json scene_json = nlohmann::json::parse(R"({
    "camera": {"type": "orthographic", "size": 1, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [8, 8]},
    "integrator": {"spp": 4, "branches": 3, "max_depth": 2, "mirror_lights": false},
    "materials": {"gold": {"type": "conductor", "metal": "Au"}, "wall": {"type": "lambert", "color": 0.5}},
    "lights": [{"type": "environment", "radiance": 1}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "gold",
                "transform": {"rotate": {"axis": [1, 0, 0], "angle": 45}}},
               {"type": "plane", "size": [10, 10], "material": "wall",
                "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, 3, 0]}]},
               {"type": "plane", "size": [10, 10], "material": "wall",
                "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, -3, 0]}]}]
  })");
  const auto scene = load_scene_json(scene_json, "mirror.json", test::source_dir() / "mirror.json");
  Film film(8, 8);
  const RenderStats stats = render(*scene.scene, scene.job, film);
  const uint64_t camera_samples = 8 * 8 * 4;
  // Camera ray, mirror bounce, then 3 branches of one ray each (branching at the mirror would trace
  // 1 + 3 x 2 rays).
  EXPECT_EQ(stats.rays, camera_samples * (2 + 3));
  // One light sample at the wall per camera sample at most (none where it lands behind the wall).
  EXPECT_LE(stats.shadow_rays, camera_samples);
  EXPECT_GT(stats.shadow_rays, camera_samples / 4);
  EXPECT_GT(film.mean(4, 4).y, 0.05f);
}

}  // namespace
}  // namespace ochre::branched_paths_test
