// Lights seen in planar mirrors (renderer/lights/planar_mirrors.h) against closed-form irradiance: a Lambert
// floor lit directly and through a vertical mirror. With integrator.mirror_lights the mirrored light is
// sampled through the light's image and MIS-weighted against BSDF sampling; without it only BSDF sampling
// finds it (and a point light's reflection not at all).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "cli/render_probe.h"

namespace ochre::test::mirror_lights_test {
namespace {

// Unpolarized Fresnel reflectance of a dielectric (relative index eta) at incidence cosine c.
double fresnel_dielectric_unpolarized(double c, double eta) {
  const double s2 = 1.0 - c * c, t = std::sqrt(1.0 - s2 / (eta * eta));
  const double rs = (c - eta * t) / (c + eta * t), rp = (eta * c - t) / (eta * c + t);
  return 0.5 * (rs * rs + rp * rp);
}

// A point light of intensity I at (0, 0, h) over a Lambert floor (albedo rho, z = 0), a black-glass mirror
// (a high index, 4, so the image is bright) in the plane x = d. A floor point p receives I cos / r^2 from the
// light and F(cos_m) I cos / r'^2 from its image at (2d, 0, h); max_depth 2 leaves out floor -> mirror ->
// floor paths.
TEST(MirrorLights, PointLightAndItsImageInAnOpaqueDielectricLightAFloor) {
  const double rho = 0.5, I = 10.0, h = 1.0, d = 1.2, view = 2.0, eta = 4.0;
  const int res = 16;
  const auto scene = [&](bool mirror_lights) {
    return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": {}, "eye": [0, 0, 5], "target": [0, 0, 0]}},
    "film": {{"resolution": [{}, {}]}},
    "integrator": {{"spp": 256, "max_depth": 2, "mirror_lights": {}}},
    "materials": {{"floor": {{"type": "lambert", "color": {}}},
                  "glass": {{"type": "dielectric", "ior": {}, "opaque": 1}}}},
    "lights": [{{"type": "point", "position": [0, 0, {}], "intensity": {}}}],
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "floor"}},
               {{"type": "plane", "size": [10, 10], "material": "glass",
                 "transform": [{{"rotate": {{"axis": [0, 1, 0], "angle": 90}}}}, {{"translate": [{}, 0, 0]}}]}}]
  }})",
                       view, res, res, mirror_lights, rho, eta, h, I, d);
  };
  const LuminanceImage with = render_luminance(scene(true)), without = render_luminance(scene(false));
  ASSERT_EQ(with.width, res);
  double worst = 0.0, worst_direct_only = 0.0, image_share = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      double direct = 0.0, mirrored = 0.0;  // averaged over the pixel (box filter), 8 x 8 points
      for (int sj = 0; sj < 8; ++sj)
        for (int si = 0; si < 8; ++si) {
          const double x = (i + (si + 0.5) / 8) / res * view - view / 2;
          const double y = view / 2 - (j + (sj + 0.5) / 8) / res * view;
          const double r2 = x * x + y * y + h * h;
          direct += rho / M_PI * I * (h / std::sqrt(r2)) / r2 / 64.0;
          const double dx = 2 * d - x, r2_image = dx * dx + y * y + h * h;
          const double cos_mirror = dx / std::sqrt(r2_image);
          mirrored += rho / M_PI * I * fresnel_dielectric_unpolarized(cos_mirror, eta) *
                      (h / std::sqrt(r2_image)) / r2_image / 64.0;
        }
      worst = std::max(worst, std::fabs(with.at(i, j) / (direct + mirrored) - 1.0));
      worst_direct_only = std::max(worst_direct_only, std::fabs(without.at(i, j) / direct - 1.0));
      image_share = std::max(image_share, mirrored / (direct + mirrored));
    }
  std::printf(
      "point light and its image: worst per-pixel error %.4f (image up to %.1f %% of the light); "
      "without mirror lights the image is missing: worst error against the direct light alone %.4f\n",
      worst, 100 * image_share, worst_direct_only);
  EXPECT_GT(image_share, 0.1);
  EXPECT_LT(worst, 0.005);
  EXPECT_LT(worst_direct_only, 0.005);
}

// Irradiance at p on the floor (normal +z) from a one-sided disk light of radiance L facing down (centre c,
// radius R): midpoint quadrature in polar coordinates.
double disk_irradiance(double px, double cx, double cz, double R, double L) {
  const int nr = 400, nphi = 800;
  double e = 0.0;
  for (int a = 0; a < nr; ++a)
    for (int b = 0; b < nphi; ++b) {
      const double r = (a + 0.5) / nr * R, phi = (b + 0.5) / nphi * 2 * M_PI;
      const double dx = cx + r * std::cos(phi) - px, dy = r * std::sin(phi), dz = cz;
      const double d2 = dx * dx + dy * dy + dz * dz;
      e += L * (dz * dz / d2) / d2 * r * (R / nr) * (2 * M_PI / nphi);  // cos_floor cos_light / d^2 dA
    }
  return e;
}

// An emissive disk (radius 0.5, facing down at height 1) over a Lambert floor, a perfect mirror (conductor
// eta 0, k 1: reflectance 1 at every angle) in the plane x = 1: the floor at x = 0.8 sees the disk and, about
// as brightly, its image centred at x = 2. Both strategies must give the same, right answer.
TEST(MirrorLights, AreaLightSeenInAPerfectMirrorMatchesQuadrature) {
  const double rho = 0.8, L = 3.0, px = 0.8;
  const auto scene = [&](bool mirror_lights) {
    return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.02, "eye": [{}, 0, 0.5], "target": [{}, 0, 0]}},
    "film": {{"resolution": [4, 4]}},
    "integrator": {{"spp": 4096, "max_depth": 2, "mirror_lights": {}}},
    "materials": {{"floor": {{"type": "lambert", "color": {}}},
                  "mirror": {{"type": "conductor", "eta": 0, "k": 1}},
                  "lamp": {{"type": "emission", "color": 1.0, "strength": {}}}}},
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "floor"}},
               {{"type": "plane", "size": [10, 10], "material": "mirror",
                 "transform": [{{"rotate": {{"axis": [0, 1, 0], "angle": 90}}}}, {{"translate": [1, 0, 0]}}]}},
               {{"type": "disk", "radius": 0.5, "segments": 1024, "material": "lamp",
                 "transform": [{{"rotate": {{"axis": [1, 0, 0], "angle": 180}}}}, {{"translate": [0, 0, 1]}}]}}]
  }})",
                       px, px, mirror_lights, rho, L);
  };
  const double direct = rho / M_PI * disk_irradiance(px, 0.0, 1.0, 0.5, L);
  const double mirrored = rho / M_PI * disk_irradiance(px, 2.0, 1.0, 0.5, L);
  const double without = render_luminance(scene(false)).mean(0, 0, 4, 4);
  std::printf(
      "disk light and its image: expected %.5f (direct %.5f + mirrored %.5f), BSDF sampling only %.5f\n",
      direct + mirrored, direct, mirrored, without);
  EXPECT_GT(mirrored, 0.3 * direct);
  EXPECT_NEAR(without / (direct + mirrored), 1.0, 0.03);
  // Each polarization mode carries the mirror's Mueller matrix its own way.
  for (const char* mode : {"off", "intensity", "stokes"}) {
    const double with =
        render_luminance(scene(true), fmt::format("--polarization {}", mode)).mean(0, 0, 4, 4);
    std::printf("  with mirror lights, mode %s: %.5f\n", mode, with);
    EXPECT_NEAR(with / (direct + mirrored), 1.0, 0.005) << mode;
  }
}

// Polarization through the mirror: a polarized disk light seen in a gold mirror from a glossy black-glass
// floor (GGX alpha 0.3: a polarizing non-delta lobe), through a linear polarizer on the lens at 0 and 90
// degrees. Light sampled through the mirror's image must carry the same Mueller product as BSDF-sampled
// paths: the two strategies agree in both polarization modes.
TEST(MirrorLights, PolarizedLightThroughAGoldMirrorAgreesWithBsdfSampling) {
  const auto scene = [&](bool mirror_lights, int analyzer) {
    return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 0.02, "eye": [0.8, 0, 0.5], "target": [0.8, 0, 0],
               "polarizer": {{"angle": {}}}}},
    "film": {{"resolution": [4, 4]}},
    "integrator": {{"spp": 4096, "max_depth": 2, "mirror_lights": {}}},
    "materials": {{"floor": {{"type": "dielectric", "ior": 1.5, "roughness": 0.3}},
                  "mirror": {{"type": "conductor", "metal": "Au"}},
                  "lamp": {{"type": "emission", "color": 1.0, "strength": 3}}}},
    "shapes": [{{"type": "plane", "size": [10, 10], "material": "floor"}},
               {{"type": "plane", "size": [10, 10], "material": "mirror",
                 "transform": [{{"rotate": {{"axis": [0, 1, 0], "angle": 90}}}}, {{"translate": [1, 0, 0]}}]}},
               {{"type": "disk", "radius": 0.5, "segments": 256, "material": "lamp", "polarizer": {{"axis": [1, 1, 0]}},
                 "transform": [{{"rotate": {{"axis": [1, 0, 0], "angle": 180}}}}, {{"translate": [0, 0, 1]}}]}}]
  }})",
                       analyzer, mirror_lights);
  };
  for (const char* mode : {"intensity", "stokes"}) {
    double across[2] = {};
    for (int a = 0; a < 2; ++a) {
      const std::string args = fmt::format("--polarization {}", mode);
      const double with = render_luminance(scene(true, 90 * a), args).mean(0, 0, 4, 4);
      const double without = render_luminance(scene(false, 90 * a), args).mean(0, 0, 4, 4);
      std::printf("mode %s, analyzer %d degrees: with mirror lights %.6f, BSDF sampling only %.6f\n", mode,
                  90 * a, with, without);
      EXPECT_NEAR(with / without, 1.0, 0.01) << mode << " " << 90 * a;
      across[a] = with;
    }
    EXPECT_GT(std::abs(across[0] / across[1] - 1.0), 0.1) << "the analyzer must see polarized light";
  }
}

}  // namespace
}  // namespace ochre::test::mirror_lights_test
