// Hero-wavelength sampling: spot values of the visible pdf, normalization, inverse-CDF
// consistency, rotation, uniform and fixed sampling, termination of secondary wavelengths.

#include "spectra/sampled_wavelengths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support/spectrum_lanes.h"

using ochre::test::lanes;

namespace ochre::sampled_wavelengths_test {
namespace {

// Composite Simpson rule of the visible pdf over [a, b].
double integrate_pdf(double a, double b, int intervals = 4700) {
  const double h = (b - a) / intervals;
  double sum = visible_wavelength_pdf(float(a)) + visible_wavelength_pdf(float(b));
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * visible_wavelength_pdf(float(a + i * h));
  return sum * h / 3.0;
}

TEST(SampledWavelengths, VisibleSpotValues) {
  struct Spot {
    float u, lambda, inverse_pdf;
  };
  for (const Spot s :
       {Spot{0.1f, 424.343f, 465.291f}, Spot{0.5f, 545.903f, 254.643f}, Spot{0.8f, 635.381f, 400.432f}}) {
    const float lambda = sample_visible_wavelength(s.u);
    EXPECT_NEAR(lambda, s.lambda, 1e-3) << "u = " << s.u;
    EXPECT_NEAR(1.0f / visible_wavelength_pdf(lambda), s.inverse_pdf, 2e-3) << "u = " << s.u;
  }
}

TEST(SampledWavelengths, VisiblePdfIntegratesToOne) {
  EXPECT_NEAR(integrate_pdf(kLambdaMin, kLambdaMax), 1.0, 1e-4);
  EXPECT_EQ(visible_wavelength_pdf(359.0f), 0.0f);
  EXPECT_EQ(visible_wavelength_pdf(831.0f), 0.0f);
}

TEST(SampledWavelengths, SamplingIsTheInverseCdfOfThePdf) {
  EXPECT_NEAR(sample_visible_wavelength(0.0f), kLambdaMin, 1e-3);
  EXPECT_NEAR(sample_visible_wavelength(std::nextafter(1.0f, 0.0f)), kLambdaMax, 1e-2);
  for (float u : {0.05f, 0.25f, 0.5f, 0.7f, 0.95f})
    EXPECT_NEAR(integrate_pdf(kLambdaMin, sample_visible_wavelength(u), 2000), u, 2e-4) << "u = " << u;
}

TEST(SampledWavelengths, HeroPdfsEqualTheDensityAtTheirWavelengths) {
  // sample_visible computes each pdf from tanh(w (538 - lambda)) without a cosh: it must be the pdf of
  // the wavelength it returns.
  for (float u : {0.0f, 0.013f, 0.2f, 0.49f, 0.77f, 0.999f}) {
    const SampledWavelengths w = SampledWavelengths::sample_visible(u);
    for (int i = 0; i < kSpectrumSamples; ++i)
      EXPECT_NEAR(w.pdf()[i], visible_wavelength_pdf(w[i]), 2e-6f * visible_wavelength_pdf(w[i]))
          << "u = " << u << " lane " << i;
  }
}

TEST(SampledWavelengths, HistogramFollowsPdf) {
  constexpr int kBins = 47, kSamples = 400000;
  std::vector<int> counts(kBins, 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int n = 0; n < kSamples; ++n) {
    const float lambda = sample_visible_wavelength(uniform(rng));
    counts[std::min(kBins - 1, int((lambda - kLambdaMin) / 10.0f))]++;
  }
  for (int b = 0; b < kBins; ++b) {
    const double expected = kSamples * integrate_pdf(kLambdaMin + 10.0 * b, kLambdaMin + 10.0 * (b + 1), 100);
    EXPECT_NEAR(counts[b], expected, 5.0 * std::sqrt(expected) + 1.0) << "bin " << b;
  }
}

TEST(SampledWavelengths, HeroRotationStratifiesTheLanes) {
  std::vector<float> every_stratum;
  for (int i = 0; i < kSpectrumSamples; ++i) every_stratum.push_back(float(i));
  for (float u : {0.0f, 0.13f, 0.5f, 0.99f}) {
    const auto w = SampledWavelengths::sample_visible(u);
    std::vector<float> strata;
    for (int i = 0; i < kSpectrumSamples; ++i) {
      const float ui = std::fmod(u + float(i) / kSpectrumSamples, 1.0f);
      EXPECT_NEAR(w[i], sample_visible_wavelength(ui), 1e-3f);
      EXPECT_NEAR(w.pdf()[i], visible_wavelength_pdf(w[i]), 2e-6f * w.pdf()[i]);
      strata.push_back(std::floor(ui * kSpectrumSamples));
    }
    std::sort(strata.begin(), strata.end());
    EXPECT_EQ(strata, every_stratum) << "one lane per 1/" << kSpectrumSamples << " of the CDF, u = " << u;
  }
}

TEST(SampledWavelengths, UniformSampling) {
  const auto w = SampledWavelengths::sample_uniform(0.1f);
  for (int i = 0; i < kSpectrumSamples; ++i) {  // 0.1 + i / kSpectrumSamples of the range, below 1
    EXPECT_NEAR(w[i], 360.0f + (0.1f + float(i) / kSpectrumSamples) * 470.0f, 1e-3);
    EXPECT_FLOAT_EQ(w.pdf()[i], 1.0f / 470.0f);
  }
  const auto narrow = SampledWavelengths::sample_uniform(0.9f, 400.0f, 700.0f);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    EXPECT_GE(narrow[i], 400.0f);
    EXPECT_LE(narrow[i], 700.0f);
    EXPECT_FLOAT_EQ(narrow.pdf()[i], 1.0f / 300.0f);
  }
}

TEST(SampledWavelengths, FixedHasUnitPdf) {
  const auto w = SampledWavelengths::fixed(lanes({450.0f, 500.0f, 550.0f, 600.0f}));
  EXPECT_EQ(w.lambda(), lanes({450.0f, 500.0f, 550.0f, 600.0f}));
  EXPECT_EQ(w.pdf(), SampledSpectrum(1.0f));
  EXPECT_FALSE(w.secondary_terminated());
}

TEST(SampledWavelengths, TerminateSecondaryKeepsTheHeroUnbiased) {
  auto w = SampledWavelengths::sample_visible(0.3f);
  const float hero_pdf = w.pdf()[0];
  w.terminate_secondary();
  EXPECT_TRUE(w.secondary_terminated());
  EXPECT_FLOAT_EQ(w.pdf()[0], hero_pdf / kSpectrumSamples);
  for (int i = 1; i < kSpectrumSamples; ++i) EXPECT_EQ(w.pdf()[i], 0.0f);
  w.terminate_secondary();  // idempotent
  EXPECT_FLOAT_EQ(w.pdf()[0], hero_pdf / kSpectrumSamples);
}

}  // namespace
}  // namespace ochre::sampled_wavelengths_test
