// GGX distribution: normalization of D, the projected-area identity that ties Lambda to D, the
// visible-normal sampler against its density (chi-square), and hard numerical cases.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "materials/chi2_test.h"
#include "materials/core/pcg32.h"
#include "materials/lobes/microfacet_ggx.h"
#include "materials/material_test_support.h"
#include "materials/polarization_test_support.h"

namespace ochre::test::microfacet_test {
namespace {

// Midpoint quadrature of f(m) over the upper hemisphere in (theta, phi).
template <class F>
double hemisphere_integral(F f, int nt, int np) {
  const double theta_max = kPi / 2;
  double sum = 0.0;
  for (int i = 0; i < nt; ++i) {
    const double theta = theta_max * (i + 0.5) / nt;
    for (int j = 0; j < np; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / np;
      const Vec3 m(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                   float(std::cos(theta)));
      sum += f(m) * std::sin(theta);
    }
  }
  return sum * (theta_max / nt) * (2 * kPi / np);
}

TEST(Ggx, NormalDistributionIsNormalized) {
  // Integral of D(m) cos(theta_m) over the hemisphere = 1 (Walter et al. 2007 Eq. 4).
  for (auto [ax, ay] : {std::pair{0.05f, 0.05f}, {0.2f, 0.2f}, {0.5f, 0.5f}, {1.0f, 1.0f}, {0.1f, 0.4f}}) {
    const GgxDistribution ggx(ax, ay);
    const double integral = hemisphere_integral([&](const Vec3& m) { return ggx.d(m) * m.z; }, 4000, 256);
    EXPECT_NEAR(integral, 1.0, 2e-3) << ax << " " << ay;
  }
  EXPECT_NEAR(GgxDistribution(0.3f).d(Vec3(0, 0, 1)), 1 / (kPi * 0.09f), 1e-4f);
}

TEST(Ggx, ProjectedAreaIdentityTiesLambdaToD) {
  // Heitz 2014 Eq. 2: integral of G1(v) max(0, v.m) D(m) dm = v.z for every v.
  for (auto [ax, ay] : {std::pair{0.2f, 0.2f}, {0.6f, 0.6f}, {1.0f, 1.0f}, {0.15f, 0.5f}}) {
    const GgxDistribution ggx(ax, ay);
    for (float theta : {0.0f, 0.7f, 1.3f, 1.5f}) {
      const Vec3 v = direction(theta, 0.8f);
      const double integral = hemisphere_integral(
          [&](const Vec3& m) { return ggx.g1(v) * std::max(0.0f, dot(v, m)) * ggx.d(m); }, 1500, 256);
      EXPECT_NEAR(integral, v.z, 3e-3) << ax << " " << ay << " " << theta;
      // The visible-normal density integrates to 1.
      const double pdf_integral =
          hemisphere_integral([&](const Vec3& m) { return ggx.visible_normal_pdf(v, m); }, 1500, 256);
      EXPECT_NEAR(pdf_integral, 1.0, 3e-3 / std::max(v.z, 0.07f)) << ax << " " << theta;
    }
  }
  // Isotropic closed form: Lambda = (-1 + sqrt(1 + alpha^2 tan^2)) / 2.
  const GgxDistribution ggx(0.4f);
  const Vec3 v = direction(1.0f, 2.0f);
  const float t = std::tan(1.0f);
  EXPECT_NEAR(ggx.lambda(v), 0.5f * (-1 + std::sqrt(1 + 0.16f * t * t)), 1e-6f);
  EXPECT_EQ(ggx.lambda(Vec3(0, 0, 1)), 0.0f);
}

// A lobe whose "directions" are the sampled visible normals, so the chi-square test of
// tests/materials/chi2_test.h checks sample_visible_normal() against visible_normal_pdf().
class VisibleNormalLobe final : public Lobe {
 public:
  explicit VisibleNormalLobe(const GgxDistribution& ggx) : ggx_(ggx) {}
  uint32_t flags() const override { return kLobeReflection | kLobeGlossy; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& m, const SampledWavelengths&) const override {
    return SampledSpectrum(m.z > 0.0f ? ggx_.visible_normal_pdf(wo, m) / m.z : 0.0f);
  }
  float pdf(const Vec3& wo, const Vec3& m, const SampledWavelengths&) const override {
    return ggx_.visible_normal_pdf(wo, m);
  }
  std::optional<LobeSample> sample(const Vec3& wo, float, const Vec2& u,
                                   const SampledWavelengths& l) const override {
    LobeSample s;
    s.wi = ggx_.sample_visible_normal(wo, u.x, u.y);
    s.pdf = pdf(wo, s.wi, l);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.weight = SampledSpectrum(1.0f);
    return s;
  }
  SampledSpectrum albedo_hint(const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(1.0f);
  }

 private:
  GgxDistribution ggx_;
};

TEST(Ggx, VisibleNormalSamplingMatchesItsDensity) {
  struct Case {
    float ax, ay, theta;
    bool fine = false;  // finer cells for the anisotropic lobe: narrow in phi near the pole
  };
  // Not sharper than alpha ~0.3 at the pole: the harness's cells are 0.05 wide in cos theta, and D
  // varies there on a scale of alpha^2 / 2 in cos theta, too fast for its per-cell Simpson rule.
  const Case cases[] = {{0.4f, 0.4f, 0.0f},
                        {0.2f, 0.2f, 0.6f},
                        {0.3f, 0.3f, 1.0f},
                        {0.8f, 0.8f, 1.5f},
                        {0.1f, 0.5f, 0.7f, true}};
  const double significance = sidak_significance(0.01, int(std::size(cases)));
  int seed = 50;
  for (const Case& c : cases) {
    const VisibleNormalLobe lobe{GgxDistribution(c.ax, c.ay)};
    const Chi2Result r = chi2_test(lobe, direction(c.theta, 0.9f), test_wavelengths(), c.fine ? 80 : 40,
                                   c.fine ? 320 : 80, 200'000, seed++);
    SCOPED_TRACE(r.summary());
    std::printf("visible normals alpha (%g, %g) theta %g: %s\n", c.ax, c.ay, c.theta, r.summary().c_str());
    EXPECT_GT(r.p_value, significance);
    EXPECT_EQ(r.samples_in_empty_cells, 0);
    EXPECT_EQ(r.pdf_mismatches, 0);
  }
}

TEST(Ggx, HardCasesStayFinite) {
  Pcg32 rng(1);
  for (float alpha : {0.0f, 1e-4f, 1e-3f, 1.0f}) {
    const GgxDistribution ggx(alpha);
    EXPECT_GE(ggx.alpha_x(), GgxDistribution::kMinAlpha);
    for (float c : {1.0f, 0.5f, 1e-7f}) {
      const Vec3 wo(std::sqrt(1 - c * c), 0.0f, c);
      EXPECT_TRUE(std::isfinite(ggx.lambda(wo)));
      EXPECT_TRUE(std::isfinite(ggx.g1(wo)));
      for (int i = 0; i < 200; ++i) {
        const Vec3 m = ggx.sample_visible_normal(wo, rng.next_float(), rng.next_float());
        EXPECT_TRUE(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z)) << alpha << " " << c;
        EXPECT_NEAR(length(m), 1.0f, 1e-5f);
        EXPECT_GE(m.z, 0.0f);
        EXPECT_TRUE(std::isfinite(ggx.d(m)));
        EXPECT_TRUE(std::isfinite(ggx.visible_normal_pdf(wo, m)));
      }
    }
    EXPECT_TRUE(std::isfinite(ggx.d(Vec3(1, 0, 0))));
    EXPECT_EQ(ggx.d(Vec3(0, 0, -1)), 0.0f);
    EXPECT_EQ(ggx.g1(Vec3(1, 0, 0)), 0.0f) << "exactly grazing is fully masked";
  }
}

}  // namespace
}  // namespace ochre::test::microfacet_test
