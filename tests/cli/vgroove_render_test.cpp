// Rendered grooves under a constant white environment, seen by an orthographic camera from (theta, phi):
// the mean pixel value relative to the environment is the groove surface's hemispherical-directional
// reflectance R(theta, phi), which materials/lobes/vgroove/vgroove_reference.h computes exactly. Checked
// for explicit groove plates (real triangles; axis-aligned and in a generic orientation, small and large),
// for the analytic `vgroove` and explicit `microgroove` materials on a plane, and for a huge tilted mirror
// (robust ray spawning).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cli/render_probe.h"
#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove_reference.h"

namespace ochre::test::vgroove_render_test {
namespace {

struct Vec {
  double x, y, z;
};

Vec rotate(const Vec& v, const Vec& k, double degrees) {  // Rodrigues, k unit
  const double a = degrees * kDegD, c = std::cos(a), s = std::sin(a), kv = k.x * v.x + k.y * v.y + k.z * v.z;
  const Vec kxv{k.y * v.z - k.z * v.y, k.z * v.x - k.x * v.z, k.x * v.y - k.y * v.x};
  return {v.x * c + kxv.x * s + k.x * kv * (1 - c), v.y * c + kxv.y * s + k.y * kv * (1 - c),
          v.z * c + kxv.z * s + k.z * kv * (1 - c)};
}

std::string json(const Vec& v) {
  return fmt::format("[{:.12f}, {:.12f}, {:.12f}]", v.x, v.y, v.z);
}

const Vec kGenericAxis{0.267261242, 0.534522484, 0.801783726};  // (1, 2, 3) / sqrt(14)

struct View {
  double theta, phi;    // degrees; phi from the axis across the grooves (the plate's y axis)
  double turn = 0.0;    // degrees about kGenericAxis, applied to the whole scene
  double centre = 0.0;  // where on the plate the camera looks (x and y), in plate units
};

// The camera, the environment and one shape with its material, all turned by view.turn.
std::string scene(const View& v, const std::string& shape, const std::string& material, double size, int spp,
                  int max_depth = 24) {
  const double t = v.theta * kDegD, p = v.phi * kDegD;
  const Vec e{std::sin(t) * std::sin(p), std::sin(t) * std::cos(p), std::cos(t)};
  const Vec target{v.centre, v.centre, 0.0};
  const Vec eye{target.x + 50 * e.x, target.y + 50 * e.y, target.z + 50 * e.z};
  const Vec up = v.theta > 1.0 ? Vec{0, 0, 1} : Vec{0, 1, 0};
  const std::string turn = v.turn == 0.0
                               ? ""
                               : fmt::format(R"(, "transform": [{{"rotate": {{"axis": {}, "angle": {}}}}}])",
                                             json(kGenericAxis), v.turn);
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": {}, "eye": {}, "target": {}, "up": {}}},
    "film": {{"resolution": [64, 64]}},
    "integrator": {{"spp": {}, "max_depth": {}, "rr_depth": {}}},
    "materials": {{"g": {}}},
    "lights": [{{"type": "environment", "radiance": 1.0}}],
    "shapes": [{}]
  }})",
                     size, json(rotate(eye, kGenericAxis, v.turn)),
                     json(rotate(target, kGenericAxis, v.turn)), json(rotate(up, kGenericAxis, v.turn)), spp,
                     max_depth, max_depth, material, shape.substr(0, shape.size() - 1) + turn + "}");
}

// Mean and standard error of the image relative to the environment alone (same pixels and samples, so
// the same wavelengths; every material here is spectrally flat).
struct Estimate {
  double mean, standard_error;
};

Estimate relative_mean(const LuminanceImage& image, const LuminanceImage& white) {
  double sum = 0, sum2 = 0, sum_white = 0;
  for (size_t i = 0; i < image.y.size(); ++i) {
    sum += image.y[i];
    sum2 += image.y[i] * image.y[i];
    sum_white += white.y[i];
  }
  const double n = static_cast<double>(image.y.size()), mean = sum / n;
  const double variance = std::max(0.0, sum2 / n - mean * mean);
  return {sum / sum_white, std::sqrt(variance / n) / (sum_white / n)};
}

const LuminanceImage& white_image(int spp) {
  static std::map<int, LuminanceImage> cache;
  auto it = cache.find(spp);
  if (it == cache.end())
    it = cache
             .emplace(spp, render_luminance(fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 1, "eye": [0, 0, 5], "target": [0, 0, 0]}},
    "film": {{"resolution": [64, 64]}}, "integrator": {{"spp": {}}}, "materials": {{}},
    "lights": [{{"type": "environment", "radiance": 1.0}}], "shapes": []}})",
                                                        spp)))
             .first;
  return it->second;
}

double exact_reflectance(double alpha, const View& v, const FacetIndex& facet) {
  return directional_reflectance(VGroove(alpha * kDegD), groove_direction(v.theta * kDegD, v.phi * kDegD),
                                 ChainModel::kRigorous, std::vector<FacetIndex>{facet})
      .reflectance[0];
}

void expect_reflectance(const std::string& what, const Estimate& got, double exact) {
  std::printf("%s: rendered %.5f +- %.5f, exact %.5f\n", what.c_str(), got.mean, got.standard_error, exact);
  EXPECT_NEAR(got.mean, exact, 3.0 * got.standard_error + 1e-4) << what;
}

constexpr const char* kSilicon = R"({"type": "conductor", "eta": 4.073, "k": 0.028})";

TEST(VGrooveRender, ExplicitGroovePlatesRenderTheExactReflectance) {
  struct Case {
    double alpha;
    View view;
    int count;  // grooves of pitch 1; the plate is `count` long too
    double size;
  };
  const Case cases[] = {
      {45, {40, 30}, 40, 4},            // small, axis-aligned
      {45, {40, 30, 37}, 40, 4},        // small, generic orientation
      {45, {55, 70, 0, 150}, 400, 4},   // large: the camera looks 150 units off the centre
      {45, {55, 70, 37, 150}, 400, 4},  // large, generic orientation
      {90, {30, 90}, 40, 4},            // along the grooves: a horizontal middle segment
      {90, {63, 90, 37}, 40, 4},       {20, {25, 10, 37}, 40, 4},  // up to 9 reflections
  };
  for (const Case& c : cases) {
    const std::string shape = fmt::format(R"({{"type": "groove_plate", "alpha": {}, "pitch": 1, "count": {},
                                             "length": {}, "material": "g"}})",
                                          c.alpha, c.count, c.count);
    const int spp = 16;
    const Estimate got =
        relative_mean(render_luminance(scene(c.view, shape, kSilicon, c.size, spp)), white_image(spp));
    expect_reflectance(fmt::format("plate alpha {} theta {} phi {} turn {} count {}", c.alpha, c.view.theta,
                                   c.view.phi, c.view.turn, c.count),
                       got, exact_reflectance(c.alpha, c.view, FacetIndex::conductor(4.073, 0.028)));
  }
}

// The image does not depend on how a surface is cut into triangles: V-groove facets 800 long and 0.71 wide
// as one triangle pair each ("tile": 0, as a user's OBJ gives them) or cut into pieces 8 or 80 long,
// axis-aligned or turned, at the plate's centre or 150 units off it, all render the exact reflectance.
// (Spawned rays used to be offset by a bound that grew with the triangle's length: the 800-long facets
// rendered +0.3 % at theta 30 and +2.7 % at theta 63, along the grooves.)
TEST(VGrooveRender, ExplicitGroovePlatesDoNotDependOnTheTessellation) {
  struct Case {
    double tile;  // facet pieces in pitches: 0, 8, 80 (a facet is 800 long, 0.71 wide)
    View view;
  };
  const Case cases[] = {
      {0, {30, 90}},      {0, {63, 90}},     {0, {63, 90, 37}},     {8, {63, 90}},          {8, {63, 90, 37}},
      {80, {63, 90, 37}}, {0, {40, 30, 37}}, {0, {55, 70, 0, 150}}, {0, {55, 70, 37, 150}},
  };
  for (const Case& c : cases) {
    const std::string shape = fmt::format(R"({{"type": "groove_plate", "alpha": 90, "pitch": 1, "count": 400,
                                             "length": 800, "tile": {}, "material": "g"}})",
                                          c.tile);
    const int spp = 16;
    const Estimate got =
        relative_mean(render_luminance(scene(c.view, shape, kSilicon, 4, spp)), white_image(spp));
    const double exact = exact_reflectance(90, c.view, FacetIndex::conductor(4.073, 0.028));
    const std::string what =
        fmt::format("facets in pieces {} long (0: 800), theta {} phi {} turn {} centre {}", c.tile,
                    c.view.theta, c.view.phi, c.view.turn, c.view.centre);
    std::printf("%s: rendered %.6f +- %.6f, exact %.6f, relative %+.1e\n", what.c_str(), got.mean,
                got.standard_error, exact, got.mean / exact - 1.0);
    EXPECT_NEAR(got.mean, exact, 3.0 * got.standard_error + 2e-6) << what;
  }
}

TEST(VGrooveRender, AnalyticAndExplicitMaterialsRenderTheExactReflectance) {
  const View views[] = {{20, 0}, {61, 90, 37}, {75, 45}};
  for (const char* type : {"vgroove", "microgroove"}) {
    for (const View& v : views) {
      // The plane's dp/du is +x, the groove axis of both the plate and the materials.
      const std::string material =
          fmt::format(R"({{"type": "{}", "alpha": 45, "eta": 4.073, "k": 0.028}})", type);
      const std::string shape = R"({"type": "plane", "size": [40, 40], "material": "g"})";
      const Estimate got = relative_mean(render_luminance(scene(v, shape, material, 4, 16)), white_image(16));
      expect_reflectance(fmt::format("{} theta {} phi {} turn {}", type, v.theta, v.phi, v.turn), got,
                         exact_reflectance(45, v, FacetIndex::conductor(4.073, 0.028)));
    }
  }
}

TEST(VGrooveRender, HugeTiltedMirrorRendersTheEnvironmentAtEveryPixel) {
  // An 800 x 800 ideal mirror turned 37, 23 and 11 degrees about x, z and y: every camera ray reflects
  // once into the environment, so every pixel equals the environment's (with the same wavelengths).
  const std::string mirror = R"({
    "camera": {"type": "orthographic", "size": 1000, "eye": [0, 0, 600], "target": [0, 0, 0], "up": [0, 1, 0]},
    "film": {"resolution": [64, 64]},
    "integrator": {"spp": 16, "max_depth": 16, "rr_depth": 16},
    "materials": {"mirror": {"type": "vgroove", "alpha": 180, "metal": "mirror"}},
    "lights": [{"type": "environment", "radiance": 1.0}],
    "shapes": [{"type": "plane", "size": [800, 800], "material": "mirror",
                "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 37}}, {"rotate": {"axis": [0, 0, 1], "angle": 23}},
                              {"rotate": {"axis": [0, 1, 0], "angle": 11}}]}]
  })";
  const LuminanceImage image = render_luminance(mirror), &white = white_image(16);
  ASSERT_EQ(image.y.size(), white.y.size());
  for (size_t i = 0; i < image.y.size(); ++i)
    ASSERT_NEAR(image.y[i] / white.y[i], 1.0, 1e-5) << "pixel " << i;
}

}  // namespace
}  // namespace ochre::test::vgroove_render_test
