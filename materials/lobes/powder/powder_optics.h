#pragma once
// What the dry-powder BRDF (powder_model.h) derives from the grains' optical constants n(lambda),
// k(lambda) (docs/materials/powder.md, "Derived quantities"):
// - the single-scattering albedo rho(lambda) = Q_sca / Q_ext of a sphere of the grain radius (Lorenz-Mie,
//   materials/numerics/mie.h), the only place the radius enters;
// - the extrapolation ratio tau_o(lambda) of Eq 16 from the internal Fresnel moments C_i (light inside the
//   grain material, real index n, reaching air, total internal reflection included).

#include <vector>

namespace ochre {

enum class PowderTau { kPaper, kZhuPineWeitz, kTwoThirds };

// C_i = int_0^1 R_F(mu) mu^i dmu for light inside a medium of real index n >= 1 reaching air (R_F = 1 below
// the critical cosine), by Gauss-Legendre quadrature split at the critical cosine.
double internal_fresnel_moment(double n, int i);

// tau_o: Eq 16 as printed (2/3 (1 - R) / (1 + R), R = (3 C2 + 2 C1) / (3 C2 - 2 C1 + 2)), its inverse as in
// Zhu, Pine and Weitz 1991 (2/3 (1 + R) / (1 - R)), or 2/3 (no internal reflection).
double powder_tau_o(double n, PowderTau model = PowderTau::kPaper);

// Mie albedo of a sphere of radius b (um) with index n + i k in air at wavelength lambda (um).
double grain_albedo(double n, double k, double radius_um, double lambda_um);

}  // namespace ochre
