// LambertSphereLobe, OrenNayarLobe and ChandrasekharLobe: sampling against pdf (chi-square),
// invariants, and the exact H table of the Chandrasekhar BRDF.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "materials/core/pi.h"
#include "materials/lobes/chandrasekhar_halfspace.h"
#include "materials/lobes/lambert.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "materials/lobes/oren_nayar.h"
#include "materials/lobes/sampling_check.h"
#include "materials/numerics/h_function.h"
#include "support/spectrum_lanes.h"

namespace ochre::test::lobes_test {
namespace {

const SampledWavelengths& wavelengths() {
  static const SampledWavelengths lambda = SampledWavelengths::fixed(lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  return lambda;
}

Vec3 direction(float theta, float phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

void expect_sampling_matches_pdf(const Lobe& lobe, const char* name) {
  const Vec3 outgoing[] = {direction(0.0f, 0.0f), direction(0.9f, 1.0f), direction(1.5f, 4.0f)};
  const double significance = sidak_significance(0.01, 3);
  for (int i = 0; i < 3; ++i) {
    const Chi2Result r = chi2_test(lobe, outgoing[i], wavelengths(), 20, 40, 200'000, 77 + i);
    SCOPED_TRACE(std::string(name) + ": " + r.summary());
    EXPECT_GT(r.p_value, significance);
    EXPECT_EQ(r.weight_mismatches, 0);
    EXPECT_EQ(r.pdf_mismatches, 0);
    EXPECT_EQ(r.samples_in_empty_cells, 0);
  }
}

TEST(LambertSphereLobe, SamplingMatchesPdf) {
  const SampledSpectrum c = lanes({0.2f, 0.6f, 0.9f, 1.0f});
  expect_sampling_matches_pdf(LambertSphereLobe(LambertSphereVariant::kFull, c), "full");
  expect_sampling_matches_pdf(LambertSphereLobe(LambertSphereVariant::kFast, c), "fast");
  expect_sampling_matches_pdf(LambertSphereLobe(LambertSphereVariant::kExact, c), "exact");
}

// The lobe evaluates the model in single precision with the branchless exp (lambert_sphere.h), all the
// wavelengths at once.
TEST(LambertSphereLobe, EvaluatesTheModelPerWavelength) {
  const SampledSpectrum c = lanes({0.0f, 0.5f, 0.9f, 1.0f});
  const LambertSphereLobe lobe(LambertSphereVariant::kFull, c);
  const Vec3 wo = direction(0.7f, 0.0f), wi = direction(0.4f, 2.0f);
  const SampledSpectrum f = lobe.eval(wo, wi, wavelengths());
  for (int k = 0; k < kSpectrumSamples; ++k)
    EXPECT_EQ(f[k], lambert_sphere_full(lambert_sphere_constants(c[k]), wi.z, wo.z,
                                        std::clamp(dot(wi, wo), -1.0f, 1.0f)));
  EXPECT_TRUE(lobe.eval(wo, direction(2.0f, 0.0f), wavelengths()).is_black());
  EXPECT_EQ(lobe.flags(), uint32_t(kLobeReflection | kLobeDiffuse));
  EXPECT_FALSE(lobe.polarizes());
  // albedo_hint tracks the bond albedo (Eq 47).
  EXPECT_NEAR(lobe.albedo_hint(wo, wavelengths())[2], lambert_sphere_bond_albedo(0.9), 0.01);
}

TEST(OrenNayar, SigmaZeroIsLambertAndReciprocal) {
  const OrenNayarLobe smooth(0.0f), rough(0.5f);
  const LambertLobe lambert;
  const Vec3 wo = direction(0.6f, 0.3f), wi = direction(1.1f, 2.5f), wi_back = direction(1.1f, 0.3f);
  EXPECT_FLOAT_EQ(smooth.eval(wo, wi, wavelengths())[0], lambert.eval(wo, wi, wavelengths())[0]);
  EXPECT_FLOAT_EQ(rough.value(wo, wi), rough.value(wi, wo));
  EXPECT_GT(rough.value(wo, wi_back), rough.value(wo, wi)) << "retro-reflection";
  expect_sampling_matches_pdf(rough, "oren_nayar");
  // Directional albedo (no interreflection term): 1 at sigma = 0, then it falls with roughness.
  double previous = 2.0;
  for (float sigma : {0.0f, 0.3f, 1.0f}) {
    const OrenNayarLobe lobe(sigma);
    double albedo = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const float mu = (i + 0.5f) / n, phi = float(2 * kPiD) * (j + 0.5f) / n;
        albedo += lobe.value(direction(0.3f, 0.0f), direction(std::acos(mu), phi)) * mu;
      }
    albedo *= 2 * kPiD / (double(n) * n);
    if (sigma == 0.0f) {
      EXPECT_NEAR(albedo, 1.0, 1e-4);
    }
    EXPECT_LT(albedo, previous) << sigma;
    previous = albedo;
  }
}

TEST(Chandrasekhar, TabulatedHFunctionAndEnergy) {
  double worst = 0;
  for (double c : {0.1, 0.37, 0.8, 0.95, 0.999, 1.0})
    for (int i = 0; i <= 40; ++i) {
      const double mu = i / 40.0 * 0.97 + 0.013 * (i % 3);
      worst = std::max(worst, std::fabs(chandrasekhar_h(chandrasekhar_constants(float(c)), float(mu)) /
                                            isotropic_h_exact(mu, c) -
                                        1));
    }
  std::printf("Chandrasekhar H table: max relative error %.2e, %zu bytes\n", worst,
              chandrasekhar_table_bytes());
  EXPECT_LT(worst, 3e-4);
  // Energy: the directional albedo is 1 - H(mu) sqrt(1 - c), exactly 1 at c = 1.
  for (double c : {0.5, 1.0})
    for (double mu : {0.1, 0.5, 1.0}) {
      const ChandrasekharConstants k = chandrasekhar_constants(float(c));
      const double albedo = directional_albedo_quadrature(
          [&](double a, double b, double) { return chandrasekhar_brdf(k, float(a), float(b)); }, mu);
      EXPECT_NEAR(albedo, 1.0 - isotropic_h_exact(mu, c) * std::sqrt(1.0 - c), 2e-3) << c << " " << mu;
    }
  expect_sampling_matches_pdf(ChandrasekharLobe(lanes({0.3f, 0.6f, 0.9f, 1.0f})), "chandrasekhar");
}

}  // namespace
}  // namespace ochre::test::lobes_test
