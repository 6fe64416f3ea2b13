// CIE standard illuminants D65 and A, scaled to luminance 1 (see cie.h).

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "spectra/cie.h"
#include "spectra/embedded_tables.h"
#include "spectra/scaled_spectrum.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

namespace {

// CIE illuminant A from its defining formula (a Planckian radiator of 2856 K on the
// IPTS-68 scale, written with the historical c2 = 1.435e-2 m K and T = 2848 K).
class IlluminantASpectrum final : public Spectrum {
 public:
  float eval(float lambda_nm) const override {
    return static_cast<float>(cie_illuminant_a_relative(lambda_nm));
  }
  // Increasing over the visible range (its peak is near 1 um).
  float max_value() const override { return eval(kLambdaMax); }
};

}  // namespace

// CIE 15:2004, "Colorimetry", 3rd ed., eq. 2.1:
// S_A(lambda) = 100 (560/lambda)^5 (exp(1.435e7 / (2848 * 560)) - 1) / (exp(1.435e7 / (2848 lambda)) - 1)
double cie_illuminant_a_relative(double lambda_nm) {
  constexpr double c2_over_t = 1.435e7 / 2848.0;  // nm
  return 100.0 * std::pow(560.0 / lambda_nm, 5) * std::expm1(c2_over_t / 560.0) /
         std::expm1(c2_over_t / lambda_nm);
}

SpectrumPtr normalized_to_unit_luminance(SpectrumPtr s) {
  const float luminance = spectrum_to_xyz(*s).y;
  if (!(luminance > 0.0f) || !std::isfinite(luminance))
    throw std::invalid_argument("cannot normalize a spectrum of luminance " + std::to_string(luminance));
  return std::make_shared<ScaledSpectrum>(std::move(s), 1.0f / luminance);
}

SpectrumPtr d65() {
  static const SpectrumPtr spectrum =
      normalized_to_unit_luminance(tabulated_spectrum(embedded_table("d65_5nm.csv"), "S"));
  return spectrum;
}

SpectrumPtr illuminant_a() {
  static const SpectrumPtr spectrum = normalized_to_unit_luminance(std::make_shared<IlluminantASpectrum>());
  return spectrum;
}

}  // namespace ochre
