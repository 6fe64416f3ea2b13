// Mitsuba's own Cornell box (cbox-spectral.xml, in the external assets folder) imported, against ochre's
// Cornell box scene (scenes/cornell-box) set to the same path length, Russian roulette and sampler: the
// two are the same box (Cornell's measured data, the same camera), so their images must agree within
// noise. The comparison is of the mean luminance of the whole image and of a few regions, each with its
// standard error from the films' per-pixel variances; the same comparison against ochre's box one
// bounce longer must fail, so that the test can tell Mitsuba's path-depth convention from a neighbour.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/compare/regression_compare.h"
#include "renderer/integrator/render.h"
#include "renderer/json/json_file.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::mitsuba_cornell_box_test {
namespace {

constexpr int kSize = 48;
constexpr uint32_t kSpp = 384;

SceneOverrides small() {
  SceneOverrides o;
  o.width = kSize;
  o.height = kSize;
  o.spp = kSpp;
  return o;
}

LuminanceEstimate render_estimate(const LoadedScene& scene) {
  Film film(scene.job.settings.width, scene.job.settings.height);
  render(*scene.scene, scene.job, film);
  return luminance_from_film(film);
}

// ochre's Cornell box with Mitsuba's settings: `max_depth` scattering events, roulette from the 5th,
// independent samples.
LuminanceEstimate ochre_box(int max_depth, uint64_t seed) {
  const auto file = test::source_dir() / "scenes/cornell-box/cornell-box.json";
  nlohmann::json root = read_json_file(file, "scene file");
  root["integrator"] = {
      {"max_depth", max_depth}, {"rr_depth", 5}, {"sampler", "independent"}, {"seed", seed}};
  return render_estimate(load_scene_json(root, file.string(), file, small()));
}

struct Mean {
  double value = 0.0, standard_error = 0.0;
};

// Mean luminance over the pixels [x0, x1) x [y0, y1), with its standard error.
Mean region_mean(const LuminanceEstimate& e, int x0, int y0, int x1, int y1) {
  double sum = 0.0, variance = 0.0;
  const double n = double(x1 - x0) * (y1 - y0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      sum += e.mean_y[size_t(y) * e.width + x];
      variance += e.variance_of_mean[size_t(y) * e.width + x];
    }
  return {sum / n, std::sqrt(variance) / n};
}

// The largest |z| of the differences of the region means: the whole image, its quarters, the ceiling
// around the light, the red and the green wall.
double worst_z(const LuminanceEstimate& a, const LuminanceEstimate& b) {
  const int h = kSize / 2, q = kSize / 4;
  const int regions[][4] = {
      {0, 0, kSize, kSize}, {0, 0, h, h},     {h, 0, kSize, h}, {0, h, h, kSize},
      {h, h, kSize, kSize}, {q, 0, 3 * q, q}, {0, q, q, 3 * q}, {3 * q, q, kSize, 3 * q}};
  double worst = 0.0;
  for (const auto& r : regions) {
    const Mean ma = region_mean(a, r[0], r[1], r[2], r[3]), mb = region_mean(b, r[0], r[1], r[2], r[3]);
    const double z = (ma.value - mb.value) / std::hypot(ma.standard_error, mb.standard_error);
    worst = std::max(worst, std::abs(z));
  }
  return worst;
}

TEST(MitsubaCornellBox, SpectralBoxRendersWithinNoiseOfOchresBox) {
  OCHRE_REQUIRE_SHARED();
  const auto xml = test::shared_dir() / "assets/scenes/cornell-box-mitsuba/cbox-spectral.xml";
  const auto scene = load_scene(xml, small());
  ASSERT_EQ(scene.job.settings.max_depth, 5);  // Mitsuba's max_depth 6
  ASSERT_EQ(scene.job.settings.rr_depth, 5);
  const LuminanceEstimate mitsuba = render_estimate(scene);
  const LuminanceEstimate ochre = ochre_box(5, 1);

  // 8 regions: |z| < 4 fails a correct import with probability below 1e-3.
  const double matched = worst_z(mitsuba, ochre);
  EXPECT_LT(matched, 4.0);
  // One bounce more in ochre's box: the light of 6-event paths must show (the test is sensitive to it).
  const double longer = worst_z(mitsuba, ochre_box(6, 1));
  EXPECT_GT(longer, 6.0);
  // The per-pixel z-test of ochre-regress passes too.
  EXPECT_TRUE(compare_luminance(mitsuba, ochre).passed());
  const Mean image = region_mean(mitsuba, 0, 0, kSize, kSize),
             reference = region_mean(ochre, 0, 0, kSize, kSize);
  std::printf(
      "cbox-spectral.xml %dx%d, %u spp: mean Y %.5f +- %.5f, ochre's box %.5f +- %.5f; worst region "
      "|z| %.2f matched, %.2f against one bounce more\n",
      kSize, kSize, kSpp, image.value, image.standard_error, reference.value, reference.standard_error,
      matched, longer);
}

}  // namespace
}  // namespace ochre::mitsuba_cornell_box_test
