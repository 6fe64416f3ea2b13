// Camera sensor responses (see sensor_response.h).

#include "spectra/sensor_response.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spectra/cie.h"

namespace ochre {

namespace {
// Share of the wavelength pdf spread uniformly over the range (defensive sampling): wavelengths where the
// sensitivities are tiny still get samples, so the estimate has no holes.
constexpr double kUniformShare = 0.05;

}  // namespace

SensorResponse::SensorResponse(std::string name, const Spectrum& r, const Spectrum& g, const Spectrum& b,
                               float lambda_min, float lambda_max)
    : name_(std::move(name)), cie_(false), lambda_min_(lambda_min), lambda_max_(lambda_max) {
  if (!(lambda_min >= 1.0f && lambda_max > lambda_min + 1.0f && std::isfinite(lambda_max)))
    throw std::invalid_argument("sensor range must be [min, max] nm with min >= 1 and max > min + 1");
  bins_ = static_cast<int>(std::ceil(lambda_max - lambda_min));
  rgb_.resize(3 * static_cast<size_t>(bins_ + 1));
  const Spectrum* channels[3] = {&r, &g, &b};
  for (int k = 0; k <= bins_; ++k) {
    const float l = std::min(lambda_min + static_cast<float>(k), lambda_max);
    for (int c = 0; c < 3; ++c) rgb_[3 * k + c] = std::max(0.0f, channels[c]->eval(l));
  }
  double green = 0.0;  // trapezoids over the knots, as response_of integrates
  for (int k = 0; k < bins_; ++k)
    green += 0.5 * (std::min(lambda_max, lambda_min + k + 1.0f) - (lambda_min + k)) *
             (rgb_[3 * k + 1] + rgb_[3 * (k + 1) + 1]);
  if (!(green > 0.0)) throw std::invalid_argument("the green sensitivity is zero over the sensor's range");
  for (float& v : rgb_) v = static_cast<float>(v / green);  // a constant radiance 1 gives G = 1

  std::vector<double> weight(bins_);
  double total = 0.0;
  for (int k = 0; k < bins_; ++k) {
    for (int c = 0; c < 3; ++c) weight[k] += 0.5 * (rgb_[3 * k + c] + rgb_[3 * (k + 1) + c]);
    total += weight[k];
  }
  cdf_.assign(bins_ + 1, 0.0);
  pdf_.resize(bins_);
  const double width = lambda_max - lambda_min;
  for (int k = 0; k < bins_; ++k) {
    const double bin_width = std::min(1.0, width - k);
    const double p = (1.0 - kUniformShare) * weight[k] / total + kUniformShare * bin_width / width;
    cdf_[k + 1] = cdf_[k] + p;
    pdf_[k] = static_cast<float>(p / bin_width);
  }
  for (double& c : cdf_) c /= cdf_.back();
}

SensorPtr cie1931_sensor() {
  static const SensorPtr observer(new SensorResponse());
  return observer;
}

float SensorResponse::interpolate(int channel, float lambda_nm) const {
  if (!(lambda_nm >= lambda_min_ && lambda_nm <= lambda_max_)) return 0.0f;
  const float offset = lambda_nm - lambda_min_;
  const int k = std::min(static_cast<int>(offset), bins_ - 1);
  const float t = offset - static_cast<float>(k);
  const float a = rgb_[3 * k + channel], b = rgb_[3 * (k + 1) + channel];
  return a + t * (b - a);
}

float SensorResponse::sensitivity(int channel, float lambda_nm) const {
  if (cie_)
    return (channel == 0   ? cie_x(lambda_nm)
            : channel == 1 ? cie_y(lambda_nm)
                           : cie_z(lambda_nm)) /
           kCieYIntegral;
  return interpolate(channel, lambda_nm);
}

float SensorResponse::sample_one(float u, float& pdf) const {
  const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
  const int k = std::clamp(static_cast<int>(it - cdf_.begin()) - 1, 0, bins_ - 1);
  const double span = cdf_[k + 1] - cdf_[k];
  const double t = span > 0.0 ? (u - cdf_[k]) / span : 0.5;
  const double bin_width = std::min(1.0, static_cast<double>(lambda_max_ - lambda_min_) - k);
  pdf = pdf_[k];
  return std::min(lambda_max_, static_cast<float>(lambda_min_ + k + t * bin_width));
}

SampledWavelengths SensorResponse::sample_wavelengths(float u) const {
  if (cie_) return SampledWavelengths::sample_visible(u);
  SampledSpectrum lambda, pdf;
  for (int i = 0; i < kSpectrumSamples; ++i) lambda[i] = sample_one(hero_rotation(u, i), pdf[i]);
  return SampledWavelengths::with_pdf(lambda, pdf);
}

float SensorResponse::wavelength_pdf(float lambda_nm) const {
  if (cie_) return visible_wavelength_pdf(lambda_nm);
  if (!(lambda_nm >= lambda_min_ && lambda_nm <= lambda_max_)) return 0.0f;
  return pdf_[std::min(static_cast<int>(lambda_nm - lambda_min_), bins_ - 1)];
}

XYZ SensorResponse::response(const SampledSpectrum& L, const SampledWavelengths& lambda) const {
  if (cie_) return sampled_to_xyz(L, lambda);
  float c[3] = {0.0f, 0.0f, 0.0f};
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float pdf = lambda.pdf()[i];
    if (pdf == 0.0f) continue;
    const float w = L[i] / pdf;
    for (int k = 0; k < 3; ++k) c[k] += w * interpolate(k, lambda[i]);
  }
  const float norm = 1.0f / kSpectrumSamples;
  return {c[0] * norm, c[1] * norm, c[2] * norm};
}

XYZ SensorResponse::response_of(const Spectrum& s) const {
  if (cie_) return spectrum_to_xyz(s);
  double c[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < bins_; ++k) {  // trapezoids over the 1 nm knots
    const float l0 = lambda_min_ + static_cast<float>(k), l1 = std::min(l0 + 1.0f, lambda_max_);
    const double v0 = s.eval(l0), v1 = s.eval(l1);
    for (int ch = 0; ch < 3; ++ch)
      c[ch] += 0.5 * (l1 - l0) * (v0 * rgb_[3 * k + ch] + v1 * rgb_[3 * (k + 1) + ch]);
  }
  return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

}  // namespace ochre
