// CIE 1931 colorimetry: colour matching functions, integration, the D65 and A white points, and
// the Monte-Carlo estimator sampled_to_xyz.

#include "spectra/cie.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "spectra/constant_spectrum.h"
#include "spectra/embedded_tables.h"
#include "support/spectrum_lanes.h"

using ochre::test::lanes;

namespace ochre::cie_test {
namespace {

TEST(Cie, MatchingFunctionValues) {
  // CIE 15:2004 table at 600 nm: (1.0622, 0.631, 0.0008).
  EXPECT_NEAR(cie_x(600.0f), 1.0622f, 1e-6f);
  EXPECT_NEAR(cie_y(600.0f), 0.631f, 1e-6f);
  EXPECT_NEAR(cie_z(600.0f), 0.0008f, 1e-6f);
  EXPECT_NEAR(cie_y(555.0f), 1.0f, 1e-4f);
  // Linear interpolation between the 1 nm rows.
  EXPECT_NEAR(cie_y(600.5f), 0.5f * (cie_y(600.0f) + cie_y(601.0f)), 1e-7f);
  // Zero outside the tabulated range.
  EXPECT_EQ(cie_x(359.9f), 0.0f);
  EXPECT_EQ(cie_y(830.1f), 0.0f);
  EXPECT_GT(cie_y(830.0f), 0.0f);
}

TEST(Cie, YIntegralMatchesTable) {
  double sum = 0.0;
  for (int l = 360; l <= 830; ++l) sum += cie_y(float(l));
  EXPECT_NEAR(sum / kCieYIntegral, 1.0, 1e-6);
}

TEST(Cie, EqualEnergyHasUnitLuminanceAndEqualTristimulus) {
  const XYZ e = spectrum_to_xyz(ConstantSpectrum(1.0f));
  EXPECT_NEAR(e.y, 1.0f, 1e-6f);
  // The CIE 1931 functions have (nearly) equal integrals: E is at x = y = 1/3.
  EXPECT_NEAR(e.x, 1.0f, 1e-3f);
  EXPECT_NEAR(e.z, 1.0f, 1e-3f);
}

TEST(Cie, D65WhitePoint) {
  const XYZ w = spectrum_to_xyz(*d65());
  EXPECT_NEAR(w.x, 0.95047f, 1e-4f);
  EXPECT_NEAR(w.y, 1.0f, 1e-6f);
  EXPECT_NEAR(w.z, 1.08883f, 1e-4f);
  // Chromaticity (0.3127, 0.3290) of CIE 15:2004 Table T.3.
  EXPECT_NEAR(w.x / (w.x + w.y + w.z), 0.3127f, 1e-4f);
  EXPECT_NEAR(w.y / (w.x + w.y + w.z), 0.3290f, 1e-4f);
  // The relative shape of the table is kept: S(560) = 100, S(500) = 109.354.
  EXPECT_NEAR(d65()->eval(500.0f) / d65()->eval(560.0f), 1.09354f, 1e-5f);
}

TEST(Cie, IlluminantA) {
  // CIE 15:2004 Table T.1 values of S_A.
  EXPECT_NEAR(cie_illuminant_a_relative(560.0), 100.0, 1e-9);
  EXPECT_NEAR(cie_illuminant_a_relative(380.0), 9.7951, 1e-4);
  EXPECT_NEAR(cie_illuminant_a_relative(780.0), 241.675, 1e-3);
  const XYZ w = spectrum_to_xyz(*illuminant_a());
  // White point of A, 2-degree observer (ASTM E308-01): (109.850, 100, 35.585) / 100.
  EXPECT_NEAR(w.x, 1.09850f, 1e-4f);
  EXPECT_NEAR(w.y, 1.0f, 1e-6f);
  EXPECT_NEAR(w.z, 0.35585f, 1e-4f);
  EXPECT_FLOAT_EQ(illuminant_a()->max_value(), illuminant_a()->eval(830.0f));
}

TEST(Cie, SampledToXyzWithFixedWavelengthsIsTheWeightedMean) {
  const auto w = SampledWavelengths::fixed(lanes({450.0f, 500.0f, 550.0f, 600.0f}));
  const SampledSpectrum L = lanes({1.0f, 2.0f, 3.0f, 4.0f});
  const XYZ xyz = sampled_to_xyz(L, w);
  float y = 0.0f;
  for (int i = 0; i < kSpectrumSamples; ++i) y += L[i] * cie_y(w[i]);
  EXPECT_NEAR(xyz.y, y / kSpectrumSamples / kCieYIntegral, 1e-7f);
}

// Mean of sampled_to_xyz over n paths with wavelengths from `sampler`.
template <typename Sampler>
XYZ monte_carlo_xyz(const Spectrum& s, int n, Sampler sampler) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  double x = 0, y = 0, z = 0;
  for (int i = 0; i < n; ++i) {
    const SampledWavelengths w = sampler(uniform(rng));
    const XYZ e = sampled_to_xyz(s.sample(w), w);
    x += e.x, y += e.y, z += e.z;
  }
  return {float(x / n), float(y / n), float(z / n)};
}

TEST(Cie, SampledToXyzConvergesToSpectrumToXyz) {
  const XYZ exact = spectrum_to_xyz(*d65());
  const auto check = [&](const XYZ& mc, const char* what) {
    EXPECT_NEAR(mc.x / exact.x, 1.0f, 0.005f) << what;
    EXPECT_NEAR(mc.y / exact.y, 1.0f, 0.005f) << what;
    EXPECT_NEAR(mc.z / exact.z, 1.0f, 0.005f) << what;
  };
  check(monte_carlo_xyz(*d65(), 100000, SampledWavelengths::sample_visible), "visible");
  check(monte_carlo_xyz(*d65(), 100000, [](float u) { return SampledWavelengths::sample_uniform(u); }),
        "uniform");
  // Only the hero wavelength survives, with pdf / 4: still unbiased (more noise, so more paths).
  check(monte_carlo_xyz(*d65(), 400000,
                        [](float u) {
                          auto w = SampledWavelengths::sample_visible(u);
                          w.terminate_secondary();
                          return w;
                        }),
        "terminated secondary");
}

}  // namespace
}  // namespace ochre::cie_test
