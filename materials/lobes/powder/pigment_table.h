#pragma once
// PigmentTable: the per-wavelength quantities the dry-powder BRDF derives from a pigment's optical
// constants (powder_optics.h), tabulated once per pigment so that a shading point only interpolates:
// - rho(lambda, b): the Mie single-scattering albedo over wavelength (360-830 nm, 5 nm steps) and size
//   parameter x = 2 pi b / lambda (log-spaced over the radii 2 nm to 20 um), interpolated bilinearly in
//   (lambda, log x) so that the radius may vary over a surface (a texture);
// - tau_o(lambda) of Eq 16 for the chosen tau model.
// Tables are shared: table_for() builds each (pigment, tau model) once per process.

#include <memory>
#include <string>
#include <vector>

#include "materials/lobes/powder/powder_optics.h"
#include "spectra/spectrum.h"

namespace ochre {

class PigmentTable {
 public:
  static constexpr float kLambdaMin = 360.0f, kLambdaMax = 830.0f, kLambdaStep = 5.0f;
  static constexpr float kRadiusMin = 0.002f, kRadiusMax = 20.0f;  // um
  static constexpr int kSizes = 768;

  // n(lambda), k(lambda) of the grain material (index n + i k).
  PigmentTable(const Spectrum& n, const Spectrum& k, PowderTau tau);

  float albedo(float lambda_nm, float radius_um) const;
  float tau_o(float lambda_nm) const;
  size_t memory_bytes() const { return (rho_.size() + tau_.size()) * sizeof(float); }

  // The table of a named pigment (one of names()), built on first use.
  static std::shared_ptr<const PigmentTable> named(const std::string& pigment, PowderTau tau);
  // The built-in pigments: "hematite" (Querry 1985, randomly oriented grains: (2 o + e) / 3), "hematite_o"
  // and "hematite_e" (one ray); named_spectrum("pigment-NAME-n") and "...-k" are their optical constants.
  static const std::vector<std::string>& names();

 private:
  int lambdas_ = 0;
  std::vector<float> rho_;  // [lambda][radius]
  std::vector<float> tau_;  // [lambda]
};

}  // namespace ochre
