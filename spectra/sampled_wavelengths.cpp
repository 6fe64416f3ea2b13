// Hero-wavelength sampling (see sampled_wavelengths.h).
// Visible-importance pdf: Radziszewski, Boryczko & Alda 2009, "An improved technique for full
// spectral rendering", as used by pbrt-v4 (SampleVisibleWavelengths) and Mitsuba 3
// (sample_rgb_spectrum). The inverse CDF is evaluated in double so that u near 0 or 1 stays
// inside [360, 830] nm after rounding to float.

#include "spectra/sampled_wavelengths.h"

#include <algorithm>
#include <cmath>

namespace ochre {

namespace {

constexpr double kVisibleCenter = 538.0;
constexpr double kVisibleWidth = 0.0072;  // 1 / 138.888889
constexpr double kVisibleNorm = 0.003939804229326285;
constexpr double kVisibleCdfOffset = 0.85691062546982790;  // tanh(0.0072 (538 - 360))
constexpr double kVisibleCdfScale = 1.82750197240922670;

// tanh(w (538 - lambda)) of the wavelength sampled by u: linear in u.
float visible_tanh(float u) {
  return static_cast<float>(kVisibleCdfOffset) - static_cast<float>(kVisibleCdfScale) * u;
}

float visible_wavelength_of_tanh(float x) {
  const float lambda = static_cast<float>(kVisibleCenter) -
                       static_cast<float>(0.5 / kVisibleWidth) * std::log((1.0f + x) / (1.0f - x));
  return std::clamp(lambda, kLambdaMin, kLambdaMax);
}

// The density at that wavelength: norm / cosh^2(w (lambda - 538)) = norm (1 - x^2).
float visible_pdf_of_tanh(float x) {
  return static_cast<float>(kVisibleNorm) * (1.0f - x * x);
}

}  // namespace

float hero_rotation(float u, int i) {
  float ui = u + static_cast<float>(i) / kSpectrumSamples;
  if (ui >= 1.0f) ui -= 1.0f;
  return ui;
}

float sample_visible_wavelength(float u) {
  return visible_wavelength_of_tanh(visible_tanh(u));
}

float visible_wavelength_pdf(float lambda) {
  if (lambda < kLambdaMin || lambda > kLambdaMax) return 0.0f;
  const double c = std::cosh(kVisibleWidth * (lambda - kVisibleCenter));
  return static_cast<float>(kVisibleNorm / (c * c));
}

SampledWavelengths SampledWavelengths::sample_visible(float u) {
  SampledWavelengths w;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float x = visible_tanh(hero_rotation(u, i));
    w.lambda_[i] = visible_wavelength_of_tanh(x);
    w.pdf_[i] = visible_pdf_of_tanh(x);
  }
  return w;
}

SampledWavelengths SampledWavelengths::sample_uniform(float u, float lambda_min, float lambda_max) {
  SampledWavelengths w;
  const float pdf = 1.0f / (lambda_max - lambda_min);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float ui = hero_rotation(u, i);
    w.lambda_[i] = std::min((1.0f - ui) * lambda_min + ui * lambda_max, lambda_max);
    w.pdf_[i] = pdf;
  }
  return w;
}

SampledWavelengths SampledWavelengths::fixed(const SampledSpectrum& lambda_nm) {
  SampledWavelengths w;
  w.lambda_ = lambda_nm;
  w.pdf_ = SampledSpectrum(1.0f);
  return w;
}

SampledWavelengths SampledWavelengths::with_pdf(const SampledSpectrum& lambda_nm,
                                                const SampledSpectrum& pdf) {
  SampledWavelengths w;
  w.lambda_ = lambda_nm;
  w.pdf_ = pdf;
  return w;
}

void SampledWavelengths::terminate_secondary() {
  if (secondary_terminated()) return;
  for (int i = 1; i < kSpectrumSamples; ++i) pdf_[i] = 0.0f;
  pdf_[0] /= kSpectrumSamples;
}

bool SampledWavelengths::secondary_terminated() const {
  for (int i = 1; i < kSpectrumSamples; ++i)
    if (pdf_[i] != 0.0f) return false;
  return true;
}

}  // namespace ochre
