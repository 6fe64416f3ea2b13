// The Lambert-sphere phase function (d'Eon Eq 1), its moments (Eqs 3-4) and samplers (Eqs 6-7).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "materials/core/pi.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_phase.h"
#include "materials/lobes/sampling_check.h"

namespace ochre::test::phase_function_test {
namespace {

// 2 pi int_{-1}^{1} g(u) p(u) du by composite Simpson in theta (u = cos theta), independent of the
// Gauss rule the library uses.
template <class G>
double sphere_integral(G g, int panels = 20000) {
  const double h = kPiD / panels;
  double sum = 0.0;
  for (int k = 0; k <= panels; ++k) {
    const double theta = k * h, u = std::cos(theta);
    const double w = (k == 0 || k == panels) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += w * g(u) * lambert_sphere_phase(u) * std::sin(theta);
  }
  return 2.0 * kPiD * sum * h / 3.0;
}

TEST(LambertSpherePhase, NormalisedWithMeanCosineMinusFourNinths) {
  EXPECT_NEAR(sphere_integral([](double) { return 1.0; }), 1.0, 1e-9);
  EXPECT_NEAR(sphere_integral([](double u) { return u; }), -4.0 / 9.0, 1e-9);
  EXPECT_DOUBLE_EQ(lambert_sphere_phase(1.0), 0.0);
  EXPECT_NEAR(lambert_sphere_phase(-1.0), 2.0 / (3.0 * kPiD), 1e-15);
  EXPECT_NEAR(lambert_sphere_phase(1.0f), 0.0f, 1e-7f);
}

TEST(LambertSpherePhase, LegendreCoefficientsOfEq4) {
  const double expected[] = {1.0, -4.0 / 3.0, 5.0 / 16.0, 0.0, 1.0 / 64.0, 0.0};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(lambert_sphere_legendre_coefficient(k), expected[k], 1e-12) << k;
  // g = A_1 / 3.
  EXPECT_NEAR(lambert_sphere_legendre_coefficient(1) / 3.0, -4.0 / 9.0, 1e-12);
}

TEST(LambertSpherePhase, CdfIsTheIntegralOfThePhaseFunction) {
  EXPECT_NEAR(lambert_sphere_cdf(-1.0), 0.0, 1e-15);
  EXPECT_NEAR(lambert_sphere_cdf(1.0), 1.0, 1e-15);
  for (double u = -0.95; u < 0.96; u += 0.1) {
    const double h = 1e-5;
    const double derivative = (lambert_sphere_cdf(u + h) - lambert_sphere_cdf(u - h)) / (2 * h);
    EXPECT_NEAR(derivative, 2.0 * kPiD * lambert_sphere_phase(u), 1e-8) << u;
    EXPECT_NEAR(lambert_sphere_inverse_cdf(lambert_sphere_cdf(u)), u, 1e-12);
  }
}

// Chi-square of sampled cosines in 100 bins of equal probability under the exact CDF.
double chi2_p_value(const std::vector<double>& samples) {
  constexpr int kBins = 100;
  std::vector<double> edges(kBins + 1);
  for (int b = 0; b <= kBins; ++b) edges[b] = lambert_sphere_inverse_cdf(double(b) / kBins);
  std::vector<int> counts(kBins, 0);
  for (double u : samples) {
    const auto it = std::upper_bound(edges.begin() + 1, edges.end() - 1, u);
    ++counts[it - edges.begin() - 1];
  }
  const double expected = double(samples.size()) / kBins;
  double chi2 = 0.0;
  for (int n : counts) chi2 += (n - expected) * (n - expected) / expected;
  return regularized_gamma_q(0.5 * (kBins - 1), 0.5 * chi2);
}

TEST(LambertSpherePhase, Eq6SamplesTheExactDistribution) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> samples(1'000'000);
  double mean = 0.0;
  for (double& u : samples) {
    u = sample_lambert_sphere_cosine_exact(uniform(rng), uniform(rng), uniform(rng));
    mean += u;
  }
  mean /= double(samples.size());
  EXPECT_GT(chi2_p_value(samples), 0.01);
  EXPECT_NEAR(mean, -4.0 / 9.0, 5 * 0.5 / 1000.0);  // sigma(u) < 0.6: 5 standard errors
  // The float version is the same formula.
  EXPECT_NEAR(sample_lambert_sphere_cosine_exact(0.2f, 0.7f, 0.9f),
              sample_lambert_sphere_cosine_exact(0.2, 0.7, 0.9), 1e-6);
}

TEST(LambertSpherePhase, Eq6ChiSquareHasPowerAgainstEq7) {
  // The same test rejects the approximate sampler with enough samples: its error is real.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> samples(8'000'000);
  for (double& u : samples) u = sample_lambert_sphere_cosine_approx(uniform(rng));
  const double p = chi2_p_value(samples);
  std::printf("Eq 7 sampler, 8 M samples: chi-square p-value %.3g\n", p);
  EXPECT_LT(p, 1e-6);
}

TEST(LambertSpherePhase, Eq7MaximumErrorIsBelow6e4) {
  double worst = 0.0, at = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double xi = std::min(double(i) / 200000, 1.0 - 1e-15);
    const double error = std::fabs(sample_lambert_sphere_cosine_approx(xi) - lambert_sphere_inverse_cdf(xi));
    if (error > worst) {
      worst = error;
      at = xi;
    }
  }
  RecordProperty("eq7_max_abs_error", std::to_string(worst) + " at xi = " + std::to_string(at));
  std::printf("Eq 7: max |mu - mu_exact| = %.3e at xi = %.4f (paper claims < 5e-4)\n", worst, at);
  EXPECT_LT(worst, 6e-4);
  EXPECT_GT(worst, 5e-4) << "the paper's bound 5e-4 is exceeded (erratum, docs/materials/lambert_sphere.md)";
  // Float agrees with double.
  for (float xi : {0.0f, 0.1f, 0.5f, 0.9f, 0.999f})
    EXPECT_NEAR(sample_lambert_sphere_cosine_approx(xi), sample_lambert_sphere_cosine_approx(double(xi)),
                1e-5);
}

}  // namespace
}  // namespace ochre::test::phase_function_test
