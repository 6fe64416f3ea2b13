#pragma once
// SampledWavelengths: the kSpectrumSamples (8) hero wavelengths of one path and their pdfs.
// One uniform number u gives lambda_i = visible_sample(u + i/8 mod 1): rotated stratification
// over 360-830 nm with the visible-importance pdf of Radziszewski et al. (the one Mitsuba 3 and
// pbrt-v4 use), so the 8 samples are stratified and each follows the same marginal pdf.

#include "spectra/sampled_spectrum.h"

namespace ochre {

inline constexpr float kLambdaMin = 360.0f;
inline constexpr float kLambdaMax = 830.0f;

// Visible-importance sampling of one wavelength on [360, 830] nm:
// pdf(lambda) = 0.0039398042 / cosh^2(0.0072 (lambda - 538)).
float sample_visible_wavelength(float u);
// The fractional part of u + i/8: the rotation that stratifies the 8 hero wavelengths of one u.
float hero_rotation(float u, int i);
float visible_wavelength_pdf(float lambda);

class SampledWavelengths {
 public:
  // Hero-wavelength sampling with the visible-importance pdf.
  static SampledWavelengths sample_visible(float u);
  // Uniform over [lambda_min, lambda_max] with the same rotation.
  static SampledWavelengths sample_uniform(float u, float lambda_min = kLambdaMin,
                                           float lambda_max = kLambdaMax);
  // Fixed wavelengths with unit pdf (for BRDF evaluation tools and tests).
  static SampledWavelengths fixed(const SampledSpectrum& lambda_nm);
  // Wavelengths drawn by another sampler (a camera sensor's, sensor_response.h) with their pdfs.
  static SampledWavelengths with_pdf(const SampledSpectrum& lambda_nm, const SampledSpectrum& pdf);

  float operator[](int i) const { return lambda_[i]; }
  const SampledSpectrum& lambda() const { return lambda_; }
  const SampledSpectrum& pdf() const { return pdf_; }

  // A dispersive event keeps only the hero wavelength (pdf of the others set to 0, hero's
  // pdf divided by 4 so that the estimator stays unbiased).
  void terminate_secondary();
  bool secondary_terminated() const;

 private:
  SampledSpectrum lambda_;
  SampledSpectrum pdf_;
};

}  // namespace ochre
