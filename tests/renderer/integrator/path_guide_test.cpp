// The path guide (renderer/integrator/path_guide.h): histograms of incident light learned from training
// records, sampled times the cosine. Its densities must be true densities (the image's weights divide by
// them), its build independent of the records' order (thread-count determinism), and a guided render
// deterministic and splittable like any other, with less noise where indirect light comes from a few
// directions (the cave).
#include "renderer/integrator/path_guide.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "materials/core/pi.h"
#include "renderer/integrator/branch_choice.h"
#include "renderer/integrator/render.h"
#include "renderer/integrator/same_pixels.h"
#include "renderer/loader/scene_loader.h"
#include "support/test_paths.h"

namespace ochre::path_guide_test {
namespace {

Vec3 uniform_direction(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float z = 1.0f - 2.0f * u(rng), phi = 2.0f * kPi * u(rng);
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Records in a 1 m box whose light comes mostly from around +x and a little from everywhere.
std::vector<GuideRecord> records_of_light_from_x(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<GuideRecord> out;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 dir = uniform_direction(rng);
    const float radiance = dir.x > 0.8f ? 10.0f : 0.1f * u(rng);
    out.push_back({{u(rng), u(rng), u(rng)}, dir, radiance, 1.0f / (4.0f * kPi)});
  }
  return out;
}

bool same_cells(const PathGuide& a, const PathGuide& b, const std::vector<Vec3>& points) {
  for (const Vec3& p : points) {
    const PathGuide::Cell *ca = a.cell(p), *cb = b.cell(p);
    if ((ca == nullptr) != (cb == nullptr)) return false;
    if (ca && ca->pmf != cb->pmf) return false;
  }
  return true;
}

TEST(PathGuide, BuildDoesNotDependOnTheOrderOrSplitOfItsRecords) {
  const std::vector<GuideRecord> all = records_of_light_from_x(300000, 1);
  const PathGuide one = PathGuide::build({all});
  std::vector<GuideRecord> shuffled = all;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  const std::vector<std::vector<GuideRecord>> split = {
      std::vector<GuideRecord>(shuffled.begin(), shuffled.begin() + 12345),
      std::vector<GuideRecord>(shuffled.begin() + 12345, shuffled.end())};
  const PathGuide other = PathGuide::build(split);
  ASSERT_GT(one.usable_cells(), 0u);
  EXPECT_EQ(one.cell_count(), other.cell_count());
  std::vector<Vec3> points;
  for (const GuideRecord& r : all) points.push_back(r.p);
  EXPECT_TRUE(same_cells(one, other, points));
}

TEST(PathGuide, CellsOfFewRecordsAndUnusableRecordsAreLeftOut) {
  std::vector<GuideRecord> records = records_of_light_from_x(100000, 2);
  records.push_back({{0.5f, 0.5f, NAN}, {1, 0, 0}, 1.0f, 1.0f});       // no position
  records.push_back({{0.5f, 0.5f, 0.5f}, {1, 0, 0}, INFINITY, 1.0f});  // no figure
  records.push_back({{0.5f, 0.5f, 0.5f}, {1, 0, 0}, -1.0f, 1.0f});     // negative light
  records.push_back({{50.0f, 50.0f, 50.0f}, {1, 0, 0}, 1.0f, 1.0f});   // alone, far away
  const PathGuide guide = PathGuide::build({records});
  EXPECT_EQ(guide.cell({50.0f, 50.0f, 50.0f}), nullptr);  // its cell has one record
  EXPECT_EQ(guide.cell({-1.0f, 0.5f, 0.5f}), nullptr);    // outside the grid
  EXPECT_EQ(guide.cell({NAN, 0.5f, 0.5f}), nullptr);
  EXPECT_TRUE(PathGuide::build({}).cell({0.5f, 0.5f, 0.5f}) == nullptr);  // nothing learned
}

// The product's density integrates to 1 over the sphere, is 0 where every bin faces away from the normal,
// and sample() draws by it: the density it reports is pdf()'s, and its bins come up as often as their
// share of the product says.
TEST(PathGuide, ProductSamplingIsADensityOverTheSphere) {
  const PathGuide guide = PathGuide::build({records_of_light_from_x(300000, 3)});
  const Vec3 normal = normalize(Vec3(0.6f, 0.0f, 0.8f));
  int checked = 0;
  for (const Vec3& p : {Vec3(0.2f, 0.3f, 0.4f), Vec3(0.8f, 0.7f, 0.1f)}) {
    const PathGuide::Cell* cell = guide.cell(p);
    ASSERT_NE(cell, nullptr);
    PathGuide::Product product;
    ASSERT_TRUE(PathGuide::product(*cell, normal, &product));
    // Midpoints of a 512 x 1024 grid in (z, phi): equal solid angles, none on a bin's edge.
    double integral = 0.0;
    constexpr int kZ = 512, kPhi = 1024;  // 64 x 64 points in every bin
    for (int i = 0; i < kZ; ++i)
      for (int j = 0; j < kPhi; ++j) {
        const float z = -1.0f + (i + 0.5f) * 2.0f / kZ, phi = (j + 0.5f) * 2.0f * kPi / kPhi;
        const float r = std::sqrt(1.0f - z * z);
        integral +=
            PathGuide::pdf(product, {r * std::cos(phi), r * std::sin(phi), z}) * (4.0 * kPi / (kZ * kPhi));
      }
    EXPECT_NEAR(integral, 1.0, 1e-4);
    std::mt19937 rng(11);

    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<double> drawn(PathGuide::kBins, 0.0);
    constexpr int kDraws = 200000;
    double mean_x = 0.0;
    for (int i = 0; i < kDraws; ++i) {
      float pdf = 0.0f;
      const Vec3 dir = PathGuide::sample(product, u(rng), {u(rng), u(rng)}, &pdf);
      ASSERT_NEAR(length(dir), 1.0f, 1e-5f);
      ASSERT_EQ(pdf, PathGuide::pdf(product, dir));
      ASSERT_GT(pdf, 0.0f);
      drawn[PathGuide::bin_of(dir)] += 1.0 / kDraws;
      mean_x += dir.x / kDraws;
    }
    double worst = 0.0;
    for (int b = 0; b < PathGuide::kBins; ++b) {
      const double share = product.weight[b] / product.total;
      worst = std::max(worst, std::fabs(drawn[b] - share));
    }
    std::printf(
        "guide product at (%.1f, %.1f, %.1f): integral %.4f, worst bin share error %.5f, mean x %.3f\n", p.x,
        p.y, p.z, integral, worst, mean_x);
    EXPECT_LT(worst, 0.005);
    EXPECT_GT(mean_x, 0.5);  // the light comes from +x, and the normal leans that way
    ++checked;
  }
  EXPECT_EQ(checked, 2);
  // Facing away from all the light and half the floor: bins behind the normal weigh nothing.
  PathGuide::Product product;
  ASSERT_TRUE(PathGuide::product(*guide.cell({0.5f, 0.5f, 0.5f}), {0, 0, 1}, &product));
  for (int b = 0; b < PathGuide::kBins / 2; ++b) EXPECT_EQ(product.weight[b], 0.0f) << b;
}

// A small version of the cave (the scene guiding is for: indirect light from the torch-lit walls).
LoadedScene cave(uint32_t spp, bool guided, uint64_t seed) {
  SceneOverrides o;
  o.width = 48;
  o.height = 27;
  o.spp = spp;
  o.seed = seed;
  LoadedScene scene = load_scene(test::source_dir() / "scenes" / "default" / "default.json", o);
  scene.job.settings.guiding = guided ? GuidingSetting::kOn : GuidingSetting::kOff;
  scene.job.settings.branches = 1;  // fixed, so that both variants trace the same paths per pixel
  scene.job.settings.rr_depth = 5;
  return scene;
}

Film render_film(const LoadedScene& scene) {
  Film film(scene.job.settings.width, scene.job.settings.height);
  render(*scene.scene, scene.job, film);
  return film;
}

// Half the relMSE (X, Y, Z; epsilon as ochre-diff) between two renders of different seeds: each one's
// variance, measured without a reference.
double half_relmse(const Film& a, const Film& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const XYZ p = a.mean(x, y), q = b.mean(x, y);
      const double pc[3] = {p.x, p.y, p.z}, qc[3] = {q.x, q.y, q.z};
      for (int c = 0; c < 3; ++c) {
        const double m = 0.5 * (pc[c] + qc[c]);
        sum += (pc[c] - qc[c]) * (pc[c] - qc[c]) / (m * m + 1e-2);
      }
    }
  return 0.5 * sum / (3.0 * a.width() * a.height());
}

using test::same_pixels;

TEST(GuidedRender, LessNoiseOnTheCaveForTheSamePaths) {
  const double plain = half_relmse(render_film(cave(64, false, 1)), render_film(cave(64, false, 2)));
  const double guided = half_relmse(render_film(cave(64, true, 1)), render_film(cave(64, true, 2)));
  std::printf("cave 48x27, 64 paths: relMSE per render %.4g unguided, %.4g guided (%.2fx)\n", plain, guided,
              guided / plain);
  EXPECT_LT(guided, 0.9 * plain);  // 0.83x here (a guide of 65536 training paths); 0.62x at 320x180
}

// The same bits for any thread count; and a render split into sample ranges, each part guided by the guide
// of the whole render (as `ochre render --part` trains it), merges into the whole render.
TEST(GuidedRender, DeterministicForAnyThreadCountAndSplitOfTheSampleRange) {
  LoadedScene scene = cave(8, true, 3);
  scene.job.settings.threads = 2;
  const Film whole = render_film(scene);
  scene.job.settings.threads = 1;
  EXPECT_TRUE(same_pixels(whole, render_film(scene)));

  const RenderJob resolved = resolve_branches(*scene.scene, scene.job);
  ASSERT_NE(resolved.settings.guide, nullptr);
  const PixelRect all{0, 0, resolved.settings.width, resolved.settings.height};
  Film part_a(all.x1, all.y1), part_b(all.x1, all.y1);
  render_range(*scene.scene, resolved, part_a, all, {0, 3});
  render_range(*scene.scene, resolved, part_b, all, {3, 8});
  part_b.merge(part_a);
  EXPECT_TRUE(same_pixels(whole, part_b));

  // The guide changes where samples go: not the unguided image.
  scene.job.settings.guiding = GuidingSetting::kOff;
  EXPECT_FALSE(same_pixels(whole, render_film(scene)));
}

}  // namespace
}  // namespace ochre::path_guide_test
