#pragma once
// Planck's law and the blackbody emission spectrum.
//
//   planck(lambda_nm, temperature_k) -> spectral radiance B_lambda(T) in W sr^-1 m^-2 per metre
//       of wavelength (SI), with the exact 2019 SI constants h, c, k_B; 0 for T <= 0.
//   wien_peak_nm(temperature_k)      -> wavelength of the maximum of B_lambda(T), in nm.
//   BlackbodySpectrum(temperature_k) -> B_lambda(T) / B_lambda_max(T): the colour of a blackbody,
//       normalized so its peak over ALL wavelengths is 1 (the scene sets the power).
//       Throws std::invalid_argument for a non-positive or non-finite temperature.

#include "spectra/spectrum.h"

namespace ochre {

double planck(double lambda_nm, double temperature_k);
double wien_peak_nm(double temperature_k);

class BlackbodySpectrum final : public Spectrum {
 public:
  explicit BlackbodySpectrum(float temperature_k);

  float eval(float lambda_nm) const override;
  float max_value() const override { return max_value_; }
  float temperature() const { return temperature_; }

 private:
  float temperature_;
  double normalization_;  // 1 / B_lambda at the Wien peak
  float max_value_;
};

}  // namespace ochre
