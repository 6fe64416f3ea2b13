// Planck's law (see blackbody_spectrum.h).
// B_lambda(T) = 2 h c^2 / lambda^5 / (exp(h c / (lambda k_B T)) - 1)   [W sr^-1 m^-2 m^-1]
// Constants: exact values of the 2019 SI redefinition (BIPM SI Brochure, 9th ed.).

#include "spectra/blackbody_spectrum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ochre {

namespace {

constexpr double kPlanck = 6.62607015e-34;   // J s
constexpr double kLightSpeed = 299792458.0;  // m / s
constexpr double kBoltzmann = 1.380649e-23;  // J / K
// x = 5 (1 - exp(-x)), root of d/dlambda B_lambda = 0, so lambda_max = h c / (x k_B T)
// (Wien's displacement law).
constexpr double kWienX = 4.965114231744276303;

}  // namespace

double planck(double lambda_nm, double temperature_k) {
  if (!(temperature_k > 0.0) || !(lambda_nm > 0.0)) return 0.0;
  const double lambda = lambda_nm * 1e-9;
  const double exponent = kPlanck * kLightSpeed / (lambda * kBoltzmann * temperature_k);
  // expm1 keeps precision in the Rayleigh-Jeans limit (small exponent); a huge exponent gives
  // inf and hence 0, the correct limit.
  return 2.0 * kPlanck * kLightSpeed * kLightSpeed / std::pow(lambda, 5) / std::expm1(exponent);
}

double wien_peak_nm(double temperature_k) {
  return kPlanck * kLightSpeed / (kWienX * kBoltzmann * temperature_k) * 1e9;
}

BlackbodySpectrum::BlackbodySpectrum(float temperature_k) : temperature_(temperature_k) {
  if (!(temperature_k > 0.0f) || !std::isfinite(temperature_k))
    throw std::invalid_argument("blackbody temperature must be positive and finite, got " +
                                std::to_string(temperature_k) + " K");
  normalization_ = 1.0 / planck(wien_peak_nm(temperature_k), temperature_k);
  if (!std::isfinite(normalization_))
    throw std::invalid_argument("blackbody temperature " + std::to_string(temperature_k) +
                                " K is out of range");
  // B_lambda is unimodal: over [360, 830] nm its maximum is the peak or an end of the range.
  const double peak = wien_peak_nm(temperature_k);
  max_value_ =
      (peak >= kLambdaMin && peak <= kLambdaMax) ? 1.0f : std::max(eval(kLambdaMin), eval(kLambdaMax));
}

float BlackbodySpectrum::eval(float lambda_nm) const {
  return static_cast<float>(planck(lambda_nm, temperature_) * normalization_);
}

}  // namespace ochre
