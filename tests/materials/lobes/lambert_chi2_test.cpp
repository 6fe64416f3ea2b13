// sample() against pdf() for the Lambert lobe with the reusable chi-square test, and the test's
// own power: it must reject a lobe whose pdf() does not describe its sampling.

#include <gtest/gtest.h>

#include <cmath>

#include "materials/chi2_test.h"
#include "materials/core/sampling.h"
#include "materials/lobes/lambert.h"
#include "materials/material_test_support.h"

namespace ochre::test::lambert_chi2_test {
namespace {

// Samples the cosine-weighted hemisphere but claims a uniform hemisphere pdf (1 / 2pi). Its
// sample weights are consistent with that claim (eval |cos| / pdf), so only the chi-square
// statistic can see the error.
class WrongPdfLobe final : public Lobe {
 public:
  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const override {
    return SampledSpectrum(wo.z > 0.0f && wi.z > 0.0f ? kInvPi : 0.0f);
  }
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const override {
    return wo.z > 0.0f && wi.z > 0.0f ? 0.5f * kInvPi : 0.0f;
  }
  std::optional<LobeSample> sample(const Vec3& wo, float, const Vec2& u,
                                   const SampledWavelengths& lambda) const override {
    if (wo.z <= 0.0f) return std::nullopt;
    LobeSample s;
    s.wi = sample_cosine_hemisphere(u);
    if (s.wi.z <= 0.0f) return std::nullopt;
    s.pdf = pdf(wo, s.wi, lambda);
    s.weight = eval(wo, s.wi, lambda) * (s.wi.z / s.pdf);
    return s;
  }
  SampledSpectrum albedo_hint(const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(1.0f);
  }
};

constexpr double kAlpha = 0.01;

Vec3 direction(float theta, float phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// The concentric disk map computes its sines and cosines by short series: every point must be the
// Shirley-Chiu point within float rounding, on the unit disk, over a grid that includes the diagonals
// (where the two branches meet) and the edges of the square.
TEST(Sampling, ConcentricDiskMatchesTheTrigonometricMapping) {
  constexpr int kSteps = 257;
  float worst = 0.0f;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j) {
      const Vec2 u{i / float(kSteps - 1) * 0.99999994f, j / float(kSteps - 1) * 0.99999994f};
      const double ox = 2.0 * u.x - 1.0, oy = 2.0 * u.y - 1.0;
      double rx = 0.0, ry = 0.0;
      if (ox != 0.0 || oy != 0.0) {
        const bool first = std::fabs(ox) > std::fabs(oy);
        const double r = first ? ox : oy;
        const double theta = first ? M_PI / 4 * (oy / ox) : M_PI / 2 - M_PI / 4 * (ox / oy);
        rx = r * std::cos(theta);
        ry = r * std::sin(theta);
      }
      const Vec2 d = sample_uniform_disk_concentric(u);
      worst = std::max(worst, static_cast<float>(std::hypot(d.x - rx, d.y - ry)));
      ASSERT_LE(d.x * d.x + d.y * d.y, 1.0f + 1e-6f);
    }
  EXPECT_LT(worst, 4e-7f);
}

TEST(Chi2, IncompleteGammaMatchesKnownValues) {
  // Q(1, x) = e^-x; chi-square with 2 dof: p = e^(-x/2); Q(0.5, x) = erfc(sqrt(x)).
  EXPECT_NEAR(regularized_gamma_q(1.0, 2.5), std::exp(-2.5), 1e-12);
  EXPECT_NEAR(regularized_gamma_q(1.0, 0.3), std::exp(-0.3), 1e-12);
  EXPECT_NEAR(regularized_gamma_q(0.5, 4.0), std::erfc(2.0), 1e-12);
  EXPECT_NEAR(regularized_gamma_q(0.5, 0.2), std::erfc(std::sqrt(0.2)), 1e-12);
  // Chi-square critical value for 100 dof at p = 0.05 is 124.342.
  EXPECT_NEAR(regularized_gamma_q(50.0, 124.342 / 2.0), 0.05, 1e-4);
  EXPECT_NEAR(sidak_significance(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(sidak_significance(0.01, 5), 1.0 - std::pow(0.99, 0.2), 1e-15);
}

TEST(Chi2, LambertSamplingMatchesItsPdf) {
  const LambertLobe lobe;
  const Vec3 outgoing[] = {direction(0.0f, 0.0f), direction(0.5f, 1.0f), direction(1.0f, 4.0f),
                           direction(1.4f, 2.0f), direction(1.55f, 5.5f)};
  const int tests = static_cast<int>(std::size(outgoing));
  const double significance = sidak_significance(kAlpha, tests);
  for (int i = 0; i < tests; ++i) {
    const Chi2Result r = chi2_test(lobe, outgoing[i], test_wavelengths(), 40, 80, 1'000'000, 1000 + i);
    SCOPED_TRACE(r.summary());
    RecordProperty("wo" + std::to_string(i), r.summary());
    EXPECT_GT(r.p_value, significance);
    EXPECT_EQ(r.weight_mismatches, 0);
    EXPECT_EQ(r.pdf_mismatches, 0);
    EXPECT_EQ(r.samples_in_empty_cells, 0);
    EXPECT_GT(r.degrees_of_freedom, 1000) << "the upper hemisphere's cells are all used";
    EXPECT_EQ(r.samples_histogrammed + r.samples_failed, 1'000'000);
  }
}

TEST(Chi2, RejectsAPdfThatDoesNotMatchTheSampling) {
  const WrongPdfLobe lobe;
  const Chi2Result r = chi2_test(lobe, direction(0.3f, 0.0f), test_wavelengths(), 40, 80, 1'000'000, 7);
  SCOPED_TRACE(r.summary());
  EXPECT_EQ(r.weight_mismatches, 0) << "the weights agree with the (wrong) pdf";
  EXPECT_LT(r.p_value, 1e-12);
  // Far fewer samples suffice to see it.
  EXPECT_LT(chi2_test(lobe, direction(0.3f, 0.0f), test_wavelengths(), 40, 80, 20'000, 8).p_value,
            sidak_significance(kAlpha, 1));
}

TEST(Chi2, CatchesWeightsInconsistentWithEvalAndPdf) {
  // The right pdf, but a weight that forgot the cosine.
  class ForgotCosine final : public Lobe {
   public:
    uint32_t flags() const override { return lambert_.flags(); }
    SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& l) const override {
      return lambert_.eval(wo, wi, l);
    }
    float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& l) const override {
      return lambert_.pdf(wo, wi, l);
    }
    std::optional<LobeSample> sample(const Vec3& wo, float uc, const Vec2& u,
                                     const SampledWavelengths& l) const override {
      std::optional<LobeSample> s = lambert_.sample(wo, uc, u, l);
      if (s) s->weight = lambert_.eval(wo, s->wi, l) / s->pdf;
      return s;
    }
    SampledSpectrum albedo_hint(const Vec3&, const SampledWavelengths&) const override {
      return SampledSpectrum(1.0f);
    }

   private:
    LambertLobe lambert_;
  };
  const Chi2Result r =
      chi2_test(ForgotCosine(), direction(0.2f, 0.0f), test_wavelengths(), 20, 40, 10'000, 3);
  EXPECT_GT(r.weight_mismatches, 9'900) << r.summary();
  EXPECT_GT(r.p_value, sidak_significance(kAlpha, 1)) << "the directions themselves are right";
}

}  // namespace
}  // namespace ochre::test::lambert_chi2_test
