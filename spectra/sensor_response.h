#pragma once
// SensorResponse: what a camera's pixel records of the radiance reaching it (docs/cameras.md). The
// default is the CIE 1931 observer (the film holds XYZ); a camera sensor replaces it with its measured
// R, G, B spectral sensitivities over its own wavelength range (the film then holds camera RGB).
//
//   cie1931_sensor()                  the observer: 360-830 nm, visible-importance wavelength sampling,
//                                     response = sampled_to_xyz (cie.h), bit for bit
//   SensorResponse(name, r, g, b, lo, hi)  tabulated sensitivities, zero outside [lo, hi] nm (an IR-cut or
//                                     IR-pass filter ends them); resampled at 1 nm; normalised so that a
//                                     constant radiance 1 gives G = 1 (as it gives Y = 1 for the observer)
//   sample_wavelengths(u)             the 8 hero wavelengths over [lo, hi]: pdf proportional to r + g + b
//                                     plus 5 % of its mean (piecewise constant per nm), so every wavelength
//                                     the sensor sees can be sampled, rotated like SampledWavelengths
//   response(L, lambda)               Monte-Carlo estimate of the channel integrals from one path
//   response_of(spectrum)             the same integrals by a 1 nm sum (white balance, tests)

#include <memory>
#include <string>
#include <vector>

#include "spectra/color_types.h"
#include "spectra/spectrum.h"

namespace ochre {

class SensorResponse {
 public:
  SensorResponse(std::string name, const Spectrum& r, const Spectrum& g, const Spectrum& b, float lambda_min,
                 float lambda_max);

  const std::string& name() const { return name_; }
  bool is_cie_observer() const { return cie_; }
  float lambda_min() const { return lambda_min_; }
  float lambda_max() const { return lambda_max_; }

  SampledWavelengths sample_wavelengths(float u) const;
  // Density of sample_wavelengths' marginal at lambda (per nm).
  float wavelength_pdf(float lambda_nm) const;
  XYZ response(const SampledSpectrum& L, const SampledWavelengths& lambda) const;
  XYZ response_of(const Spectrum& s) const;
  // Sensitivity of channel c (0 = R) at lambda, normalised (0 outside the range).
  float sensitivity(int channel, float lambda_nm) const;

 private:
  friend std::shared_ptr<const SensorResponse> cie1931_sensor();
  SensorResponse() = default;

  std::string name_ = "cie1931";
  bool cie_ = true;
  float lambda_min_ = kLambdaMin, lambda_max_ = kLambdaMax;
  int bins_ = 0;             // 1 nm bins from lambda_min_
  std::vector<float> rgb_;   // 3 per knot (bins_ + 1 knots), normalised
  std::vector<double> cdf_;  // bins_ + 1 entries, 0 .. 1
  std::vector<float> pdf_;   // per bin, per nm
  float interpolate(int channel, float lambda_nm) const;
  float sample_one(float u, float& pdf) const;
};

using SensorPtr = std::shared_ptr<const SensorResponse>;

SensorPtr cie1931_sensor();

}  // namespace ochre
