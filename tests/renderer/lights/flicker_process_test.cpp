// The flicker of flames in a frame sequence (renderer/lights/flicker_process.h, docs/lights.md#flicker): the
// process has the preset's statistics (mean, relative standard deviation, correlation time), every frame is
// a pure function of (seed, stream, frame), and the flame's state follows it.
#include "renderer/lights/flicker_process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "renderer/lights/flame_light.h"
#include "renderer/lights/light_presets.h"
#include "renderer/lights/sphere_light.h"

namespace ochre::flicker_process_test {
namespace {

struct SeriesStats {
  double mean = 0, std = 0, lag1 = 0;
};

SeriesStats stats_of(const std::vector<double>& v) {
  SeriesStats s;
  for (double x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  double var = 0, cov = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    var += (v[i] - s.mean) * (v[i] - s.mean);
    if (i + 1 < v.size()) cov += (v[i] - s.mean) * (v[i + 1] - s.mean);
  }
  s.std = std::sqrt(var / static_cast<double>(v.size()));
  s.lag1 = cov / var;
  return s;
}

TEST(FlickerProcess, FrameAloneEqualsFrameOfTheSequence) {
  OuProcess process(7, 3, 24.0, 5.3);
  for (int k = 0; k < 50; ++k) {
    EXPECT_EQ(process.value(), ou_process_value(7, 3, static_cast<uint64_t>(k), 24.0, 5.3)) << k;
    process.advance();
  }
}

TEST(FlickerProcess, DependsOnSeedAndStream) {
  EXPECT_NE(ou_process_value(1, 0, 10, 24.0, 5.0), ou_process_value(2, 0, 10, 24.0, 5.0));
  EXPECT_NE(ou_process_value(1, 0, 10, 24.0, 5.0), ou_process_value(1, 1, 10, 24.0, 5.0));
  EXPECT_EQ(hashed_standard_normal(4, 5, 6), hashed_standard_normal(4, 5, 6));
}

// The unit process: mean 0, variance 1, lag-one correlation exp(-dt / tau) with tau = 1 / (2 pi f_c).
TEST(FlickerProcess, UnitProcessHasItsCorrelationTime) {
  const double fps = 240.0, corner = 5.3;
  OuProcess process(11, 0, fps, corner);
  std::vector<double> x;
  for (int k = 0; k < 200000; ++k, process.advance()) x.push_back(process.value());
  const SeriesStats s = stats_of(x);
  const double tau = 1.0 / (2.0 * M_PI * corner);
  EXPECT_NEAR(s.mean, 0.0, 0.02);
  EXPECT_NEAR(s.std, 1.0, 0.02);
  const double tau_measured = -(1.0 / fps) / std::log(s.lag1);
  EXPECT_NEAR(tau_measured / tau, 1.0, 0.03) << tau_measured << " s against " << tau << " s";
}

// The torch preset's intensity over many frames: the preset's mean and relative standard deviation.
TEST(FlickerProcess, TorchIntensityHasThePresetStatistics) {
  const FlamePreset& torch = *find_flame_preset("torch");
  const double fps = 120.0;
  OuProcess process(3, 0, fps, torch.flicker.corner_hz);
  std::vector<double> intensity;
  for (int k = 0; k < 200000; ++k, process.advance())
    intensity.push_back(torch.intensity_cd * lognormal_factor(process.value(), torch.flicker.relative_std));
  const SeriesStats s = stats_of(intensity);
  EXPECT_NEAR(s.mean / torch.intensity_cd, 1.0, 0.01);
  EXPECT_NEAR(s.std / s.mean, torch.flicker.relative_std, 0.01);
  for (double v : intensity) ASSERT_GT(v, 0.0);
}

TEST(FlickerProcess, LognormalFactorMoments) {
  // E[exp(s X - s^2/2)] = 1 and Var = exp(s^2) - 1 = r^2 exactly; check by quadrature over X ~ N(0, 1).
  for (double r : {0.05, 0.25, 1.0}) {
    double m1 = 0, m2 = 0;
    for (int i = -8000; i <= 8000; ++i) {
      const double x = i * 1e-3, w = std::exp(-0.5 * x * x) / std::sqrt(2 * M_PI) * 1e-3;
      const double f = lognormal_factor(x, r);
      m1 += w * f;
      m2 += w * f * f;
    }
    EXPECT_NEAR(m1, 1.0, 1e-6) << r;
    EXPECT_NEAR(std::sqrt(m2 - m1 * m1), r, 1e-5) << r;
  }
}

TEST(FlameLight, StateFollowsTheProcessAndStaysPositive) {
  FlameLight flame;
  flame.position = {1, 2, 3};
  flame.cct_k = 1700;
  flame.intensity_cd = 5;
  flame.flicker = {0.25f, 5.3f, 100.0f, 0.02f};
  const FlameState a = flame_state(flame, 9, 17, 24.0), b = flame_state(flame, 9, 17, 24.0);
  EXPECT_EQ(a.intensity_cd, b.intensity_cd);
  EXPECT_EQ(a.cct_k, b.cct_k);
  EXPECT_EQ(a.position.x, b.position.x);
  EXPECT_GT(a.intensity_cd, 0.0f);
  EXPECT_NE(a.position.x, flame.position.x);
  EXPECT_NE(a.cct_k, flame.cct_k);
  const FlameState c = flame_state(flame, 9, 18, 24.0);
  EXPECT_NE(a.intensity_cd, c.intensity_cd);
  // Without flicker the flame stays at its mean.
  flame.flicker = {};
  const FlameState still = flame_state(flame, 9, 17, 24.0);
  EXPECT_EQ(still.intensity_cd, 5.0f);
  EXPECT_EQ(still.cct_k, 1700.0f);
  EXPECT_EQ(still.position.y, 2.0f);
}

// A light's intensity is memoized per thread for a path's wavelengths (spectra/memoized_spectrum.h): a flame
// given its next frame's spectrum must not read the previous frame's values at the same wavelengths.
TEST(FlameLight, NewIntensityIsSampledAfterAStateChange) {
  SphereLight light({0, 0, 0}, 0.05f, flame_spectrum(1700.0f, 5.0f));
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
  const Vec3 wall{0, 0, -1};
  const SampledSpectrum before = light.sample(wall, {0.5f, 0.5f}, lambda)->radiance;
  EXPECT_EQ(light.sample(wall, {0.5f, 0.5f}, lambda)->radiance[0], before[0]) << "the same, from the memo";
  light.set_state({0, 0, 0}, flame_spectrum(1700.0f, 10.0f));
  const SampledSpectrum after = light.sample(wall, {0.5f, 0.5f}, lambda)->radiance;
  for (int i = 0; i < kSpectrumSamples; ++i)
    EXPECT_FLOAT_EQ(after[i], 2.0f * before[i]) << "twice the candelas at " << lambda[i] << " nm";
}

TEST(LightPresets, KnownNamesAndValues) {
  EXPECT_EQ(flame_preset_names(), "torch, torch_juniper, grease_lamp, fireplace");
  EXPECT_EQ(spot_preset_names(), "led_work_light, flash");
  EXPECT_EQ(find_flame_preset("candle"), nullptr);
  // A torch gives about five times the light of a double-wicked grease lamp (Medina-Alcaide et al. 2021).
  EXPECT_NEAR(find_flame_preset("torch")->intensity_cd / find_flame_preset("grease_lamp")->intensity_cd, 5.0,
              1e-6);
  // Puffing law f = 1.5 / sqrt(D) for an 8 cm torch flame.
  EXPECT_NEAR(find_flame_preset("torch")->flicker.corner_hz, 1.5 / std::sqrt(0.08), 1e-4);
}

}  // namespace
}  // namespace ochre::flicker_process_test
