// Sampling of the powder lobe: sample() against pdf() by chi-square (with the four wavelengths equal, where
// the averaged pdf is the sampled one), the cone lobe's share of samples near backscatter, and the spectral
// MIS estimate of the directional albedo (averaged over which wavelength is the hero) against quadrature.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/core/pi.h"
#include "materials/lobes/powder/powder_lobe.h"
#include "materials/lobes/sampling_check.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre::test::powder_sampling_test {
namespace {

Vec3 direction(float theta_deg, float phi) {
  const float t = theta_deg * kDegF;
  return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

PowderLobe lobe_at(const PowderParams<float>& p, const SampledSpectrum& lambda_nm,
                   const SampledSpectrum& rho) {
  std::array<PowderParams<float>, kSpectrumSamples> params;
  std::array<PowderWavelength<float>, kSpectrumSamples> waves;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    params[i] = p;
    waves[i] = {lambda_nm[i] * 1e-3f, rho[i], 0.03f};
  }
  return PowderLobe(params, waves);
}

TEST(PowderSampling, ChiSquareOfTheMixture) {
  // The default cone (3 degrees) is tested away from the pole: at normal incidence it sits inside one ring
  // of cells, whose integration cannot resolve it; the wide cone covers normal incidence.
  struct Case {
    const char* name;
    PowderParams<float> p;
  };
  std::vector<Case> cases;
  cases.push_back({"default", {}});
  PowderParams<float> wide;
  wide.kappa = 3.0f;  // a cone wide enough for the histogram's cells to resolve
  cases.push_back({"wide cone", wide});
  PowderParams<float> rough;
  rough.surface_amplitude = 3e-4f;
  rough.correlation_length = 0.4f;
  rough.kappa = 2.0f;
  cases.push_back({"strong surface", rough});
  PowderParams<float> forward;
  forward.g = 0.6f;
  forward.kappa = 2.0f;
  cases.push_back({"g = 0.6", forward});
  const SampledWavelengths lambda = SampledWavelengths::fixed(SampledSpectrum(600.0f));
  int tests = 0;
  tests = 4 * static_cast<int>(cases.size());
  const double level = sidak_significance(0.01, tests);
  for (const Case& c : cases) {
    const PowderLobe lobe = lobe_at(c.p, SampledSpectrum(600.0f), SampledSpectrum(0.8f));
    for (float theta : {0.0f, 30.0f, 60.0f, 85.0f}) {
      if (std::string(c.name) == "default" && theta == 0.0f) continue;
      const Vec3 wo = direction(theta, 0.4f);
      const Chi2Result r = chi2_test(lobe, wo, lambda, 60, 120, 400000);
      EXPECT_GT(r.p_value, level) << c.name << " theta " << theta << ": " << r.summary();
      EXPECT_EQ(r.pdf_mismatches, 0) << c.name << " " << theta;
      EXPECT_EQ(r.weight_mismatches, 0) << c.name << " " << theta;
    }
  }
}

TEST(PowderSampling, TheConeLobePutsSamplesNearBackscatter) {
  // The viewer next to the light (a flash): the cone's samples land within a few cone widths of wo, where
  // cosine sampling puts almost none.
  const PowderLobe lobe = lobe_at(PowderParams<float>{}, SampledSpectrum(700.0f), SampledSpectrum(0.752f));
  const Vec3 wo = direction(30.0f, 0.0f);
  const PowderSampling m = lobe.mixture(0, wo);
  ASSERT_GT(m.p_cone, 0.05f);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  int near = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const auto s =
        lobe.sample(wo, u(rng), {u(rng), u(rng)}, SampledWavelengths::fixed(SampledSpectrum(700.0f)));
    if (s && std::hypot(s->wi.x - wo.x, s->wi.y - wo.y) < 3.0f * m.cone_width) ++near;
  }
  const float cosine_share = 9.0f * m.cone_width * m.cone_width;  // (3w)^2 pi / pi of the projected disk
  std::printf(
      "cone probability %.3f, width %.4f: %.2f %% of samples within 3 widths (cosine alone: %.2f %%)\n",
      m.p_cone, m.cone_width, 100.0 * near / n, 100.0 * cosine_share);
  EXPECT_GT(double(near) / n, 0.8 * m.p_cone);
  EXPECT_GT(double(near) / n, 3.0 * cosine_share);
}

// Quadrature of f cos over the hemisphere for lane i.
double albedo_by_quadrature(const PowderLobe& lobe, const Vec3& wo, const SampledWavelengths& lambda,
                            int lane) {
  // Fine near the cone: (sin^2 theta, phi) rule plus the cone region is narrow; 512^2 resolves it.
  const GaussLegendreRule us = gauss_legendre_rule(512, 0.0, 1.0),
                          phis = gauss_legendre_rule(512, 0.0, 2 * M_PI);
  double sum = 0.0;
  for (size_t a = 0; a < us.nodes.size(); ++a) {
    const double st = std::sqrt(us.nodes[a]);
    for (size_t b = 0; b < phis.nodes.size(); ++b) {
      const Vec3 wi(float(st * std::cos(phis.nodes[b])), float(st * std::sin(phis.nodes[b])),
                    float(std::sqrt(1.0 - us.nodes[a])));
      sum += us.weights[a] * phis.weights[b] * 0.5 * lobe.eval(wo, wi, lambda)[lane];
    }
  }
  return sum;
}

TEST(PowderSampling, SpectralMisEstimatesTheAlbedoOfEveryWavelength) {
  // Different wavelengths and albedos in every lane; the hero (lane 0) draws, the weights divide by the mean
  // of the lanes' mixture pdfs. Averaged over which lane is the hero (the renderer's wavelength sets are
  // rotations, so each lane is the hero equally often), every lane's albedo is estimated without bias.
  constexpr int kLanes = kSpectrumSamples;
  PowderParams<float> p;
  p.kappa = 1.0f;
  p.surface_amplitude = 1e-4f;
  p.correlation_length = 0.6f;
  std::array<float, kLanes> lambdas, rhos;
  for (int i = 0; i < kLanes; ++i) {
    lambdas[i] = 420.0f + 300.0f * float(i) / (kLanes - 1);
    rhos[i] = 0.3f + 0.6f * float(i) / (kLanes - 1);
  }
  const Vec3 wo = direction(35.0f, 0.2f);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::array<double, kLanes> sum{}, sum2{};
  const int per_rotation = 600000 / kLanes;
  for (int rotation = 0; rotation < kLanes; ++rotation) {
    SampledSpectrum l, r;
    for (int i = 0; i < kLanes; ++i)
      l[i] = lambdas[(i + rotation) % kLanes], r[i] = rhos[(i + rotation) % kLanes];
    const PowderLobe lobe = lobe_at(p, l, r);
    const SampledWavelengths lambda = SampledWavelengths::fixed(l);
    for (int s = 0; s < per_rotation; ++s) {
      const auto sample = lobe.sample(wo, u(rng), {u(rng), u(rng)}, lambda);
      for (int i = 0; i < kLanes; ++i) {
        const double w = sample ? sample->weight[i] : 0.0;
        const int original = (i + rotation) % kLanes;
        sum[original] += w;
        sum2[original] += w * w;
      }
    }
  }
  SampledSpectrum l, r;
  for (int i = 0; i < kLanes; ++i) l[i] = lambdas[i], r[i] = rhos[i];
  const PowderLobe reference = lobe_at(p, l, r);
  const int n = kLanes * per_rotation;
  for (int i = 0; i < kLanes; ++i) {
    const double mean = sum[i] / n, se = std::sqrt(std::max(0.0, sum2[i] / n - mean * mean) / n);
    const double exact = albedo_by_quadrature(reference, wo, SampledWavelengths::fixed(l), i);
    EXPECT_NEAR(mean, exact, 4.0 * se + 2e-4 * exact) << "lane " << i << " (" << lambdas[i] << " nm)";
  }
}

}  // namespace
}  // namespace ochre::test::powder_sampling_test
