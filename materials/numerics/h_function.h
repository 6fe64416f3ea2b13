#pragma once
// Numerically exact Chandrasekhar H functions of the three-term Lambert-sphere half space (d'Eon
// Eqs 22-26, characteristics Psi^(0..2) of Sec 3.1) and of the isotropic half space (Psi = c/2),
// as a validation tool for the fitted H^(0) (Eq 37) and H^(1) (Eqs 28-30), and for the exact
// Chandrasekhar BRDF. Double precision, ~1e-8 relative (the Eq 20 residual is < 2e-6 with a 48-node
// rule, see tests); costs ~0.05 ms per value: tabulate for
// rendering.
//
// Method: H(mu) = exp(-(mu/pi) int_0^inf log K(t) / (1 + mu^2 t^2) dt) (Eq 22) with the
// substitution t = tan(theta) / mu, integrated by Gauss-Legendre on panels graded geometrically
// towards theta = 0 (the integrand varies on the scale theta ~ mu and has a log singularity at
// c = 1 for the conservative modes). K(t) = 1 - 2 int_0^1 Psi(x) / (1 + t^2 x^2) dx (Eq 23 with
// s = 1/x) is summed from the even polynomial Psi = sum psi_k x^(2k) with the moments
// J_k(t) = int_0^1 x^(2k) / (1 + t^2 x^2) dx: a power series in t^2 below t = 0.5 (where the closed
// forms of Eqs 24-26 cancel catastrophically) and the recurrence J_k = (1/(2k-1) - J_(k-1)) / t^2
// from J_0 = atan(t)/t above.

#include <array>

namespace ochre {

// Psi(x) = sum_k coefficients[k] x^(2k).
struct Characteristic {
  std::array<double, 3> coefficients{};
};

// Psi^(mode)(x) of the three-term LS half space with particle albedo c (d'Eon Sec 3.1), mode 0..2.
Characteristic lambert_sphere_characteristic(int mode, double c);
// Psi(x) = c / 2: isotropic scattering.
Characteristic isotropic_characteristic(double c);

// K(t) of Eq 23 for a characteristic.
double h_dispersion(const Characteristic& psi, double t);
// K(0) = 1 - 2 int_0^1 Psi; H(infinity) = 1 / sqrt(K(0)).
double h_dispersion_at_zero(const Characteristic& psi);

// H(mu) by Eq 22 for mu >= 0 (H(0) = 1).
double h_function(const Characteristic& psi, double mu);

// Convenience wrappers.
double lambert_sphere_h_exact(int mode, double mu, double c);
double isotropic_h_exact(double mu, double c);

// The closed forms of Eqs 24-26 as printed (for tests: they agree with h_dispersion for t >~ 0.5
// and lose all precision as t -> 0).
double lambert_sphere_dispersion_closed_form(int mode, double c, double t);

}  // namespace ochre
