// The Lambertian-sphere phase function (d'Eon Eq 1) and the simulation's geometric sampler of it.

#include "tools/halfspace/phase_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "chi_square.h"
#include "materials/core/pi.h"

namespace ochre::halfspace::test::phase_function_test {
namespace {

// Composite Simpson's rule.
template <typename F>
double integrate(F f, double a, double b, int intervals = 2000) {
  const double h = (b - a) / intervals;
  double sum = f(a) + f(b);
  for (int i = 1; i < intervals; ++i) sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

Direction normalized(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  return {x / n, y / n, z / n};
}

struct SampledCosines {
  std::vector<double> counts;  // histogram of u = d.d' over equal bins of [-1, 1]
  double mean = 0.0, mean_squares = 0.0;
  double max_norm_error = 0.0;
};

SampledCosines sample_cosines(PhaseFunction phase, const Direction& d, int samples, int bins, uint64_t seed) {
  SampledCosines s;
  s.counts.assign(bins, 0.0);
  RandomSource random(seed, 0);
  for (int i = 0; i < samples; ++i) {
    const Direction out = sample_phase(phase, d, random);
    s.max_norm_error = std::max(s.max_norm_error, std::abs(dot(out, out) - 1.0));
    const double u = std::clamp(dot(out, d), -1.0, 1.0);
    s.counts[std::min(bins - 1, static_cast<int>((u + 1.0) / 2.0 * bins))] += 1.0;
    s.mean += u / samples;
    s.mean_squares += u * u / samples;
  }
  return s;
}

// Expected counts per u bin from Eq 1: N * 2 pi * integral of p over the bin.
std::vector<double> expected_counts(int samples, int bins) {
  std::vector<double> expected(bins);
  for (int b = 0; b < bins; ++b) {
    const double u0 = -1.0 + 2.0 * b / bins, u1 = -1.0 + 2.0 * (b + 1) / bins;
    expected[b] = samples * 2.0 * kPiD * integrate(lambertian_sphere_phase, u0, u1, 200);
  }
  return expected;
}

TEST(LambertianSpherePhase, MatchesEquation1Properties) {
  EXPECT_NEAR(2.0 * kPiD * integrate(lambertian_sphere_phase, -1.0, 1.0), 1.0, 1e-7) << "normalised to 1";
  const double g = 2.0 * kPiD * integrate([](double u) { return u * lambertian_sphere_phase(u); }, -1.0, 1.0);
  EXPECT_NEAR(g, -4.0 / 9.0, 1e-7) << "d'Eon: g = -4/9";
  EXPECT_NEAR(lambertian_sphere_phase(1.0), 0.0, 1e-15) << "no forward scattering";
  EXPECT_NEAR(lambertian_sphere_phase(-1.0), 2.0 / (3.0 * kPiD), 1e-15);
  // The Legendre coefficient A2 = 2 pi 5 int p P2 = 5/16 (d'Eon Eq 4).
  const double a2 =
      2.0 * kPiD * 5.0 *
      integrate([](double u) { return lambertian_sphere_phase(u) * 0.5 * (3.0 * u * u - 1.0); }, -1.0, 1.0);
  EXPECT_NEAR(a2, 5.0 / 16.0, 1e-6);
}

TEST(LambertianSpherePhase, GeometricSamplerFollowsEquation1) {
  constexpr int kSamples = 400'000, kBins = 50;
  const Direction directions[] = {{0, 0, 1}, {0, 0, -1}, normalized(1, 2, -0.5), normalized(0.3, -0.1, 0.01)};
  const std::vector<double> expected = expected_counts(kSamples, kBins);
  uint64_t seed = 11;
  for (const Direction& d : directions) {
    const SampledCosines s = sample_cosines(PhaseFunction::kLambertianSphere, d, kSamples, kBins, seed++);
    const ChiSquare chi2 = chi_square(s.counts, expected);
    SCOPED_TRACE(testing::Message() << "d = (" << d.x << ", " << d.y << ", " << d.z
                                    << "), chi2 = " << chi2.statistic << " dof " << chi2.degrees_of_freedom);
    EXPECT_LT(chi_square_z(chi2), 4.0);
    EXPECT_GE(chi2.degrees_of_freedom, kBins - 2);
    // Mean cosine g = -4/9 within 4 standard errors of the sample mean.
    const double se = std::sqrt((s.mean_squares - s.mean * s.mean) / kSamples);
    EXPECT_NEAR(s.mean, -4.0 / 9.0, 4.0 * se);
    EXPECT_LT(s.max_norm_error, 1e-12);
  }
}

TEST(LambertianSpherePhase, SamplerIsAzimuthallySymmetric) {
  // Around d = z the azimuth of the scattered direction must be uniform.
  constexpr int kSamples = 200'000, kBins = 36;
  RandomSource random(5, 0);
  std::vector<double> counts(kBins, 0.0);
  const Direction d = normalized(0.2, -0.7, 0.4);
  // A basis (e1, e2) perpendicular to d.
  const Direction e1 = normalized(0.7, 0.2, 0.0);
  const Direction e2{d.y * e1.z - d.z * e1.y, d.z * e1.x - d.x * e1.z, d.x * e1.y - d.y * e1.x};
  for (int i = 0; i < kSamples; ++i) {
    const Direction out = sample_lambertian_sphere_scattering(d, random);
    double phi = std::atan2(dot(out, e2), dot(out, e1));
    if (phi < 0.0) phi += 2.0 * kPiD;
    counts[std::min(kBins - 1, static_cast<int>(phi / (2.0 * kPiD) * kBins))] += 1.0;
  }
  const ChiSquare chi2 = chi_square(counts, std::vector<double>(kBins, double(kSamples) / kBins));
  EXPECT_LT(chi_square_z(chi2), 4.0) << chi2.statistic;
}

TEST(LambertianSpherePhase, ChiSquareRejectsAWrongSampler) {
  // The test's power: isotropic samples (mean cosine 0) against Eq 1's expected counts.
  constexpr int kSamples = 20'000, kBins = 50;
  const SampledCosines s = sample_cosines(PhaseFunction::kIsotropic, {0, 0, 1}, kSamples, kBins, 3);
  EXPECT_GT(chi_square_z(chi_square(s.counts, expected_counts(kSamples, kBins))), 10.0);
  EXPECT_NEAR(s.mean, 0.0, 4.0 * std::sqrt(1.0 / 3.0 / kSamples)) << "isotropic: mean cosine 0";
}

}  // namespace
}  // namespace ochre::halfspace::test::phase_function_test
