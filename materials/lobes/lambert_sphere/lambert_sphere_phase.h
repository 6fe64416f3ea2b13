#pragma once
// The phase function of a smooth white Lambertian sphere (d'Eon, "An analytic BRDF for materials
// with spherical Lambertian scatterers", Eq 1) with its Legendre moments (Eqs 2-4) and the two
// samplers of Sec 2.1 (Eq 6 exact, Eq 7 approximate inverse CDF).
//
// Convention: u is the cosine of the scattering angle between the propagation directions before
// and after scattering (u = +1 forward, where p = 0; u = -1 backward, where p = 2 / (3 pi)); p is
// normalised to 1 over the sphere: 2 pi * integral_{-1}^{1} p(u) du = 1.

#include <cmath>
#include <vector>

namespace ochre {

// p(u) = 2 (sqrt(1 - u^2) - u acos(u)) / (3 pi^2) = 2 (sin t - t cos t) / (3 pi^2), t = acos(u), Eq 1.
// u is clamped to [-1, 1]. Near forward scattering (t -> 0) sin t - t cos t cancels (p ~ t^3): there
// the series t^3/3 - t^5/30 + t^7/840 - t^9/45360 is used (relative error < 1e-13 for t < 0.1).
template <class T>
T lambert_sphere_phase(T u) {
  constexpr T kPiT = T(3.14159265358979323846);
  const T uc = std::fmin(T(1), std::fmax(T(-1), u));
  const T t = std::acos(uc);
  T v;
  if (t < T(0.1)) {
    const T t2 = t * t;
    v = t * t2 * (T(1) / T(3) - t2 * (T(1) / T(30) - t2 * (T(1) / T(840) - t2 / T(45360))));
  } else {
    v = std::sqrt((T(1) - uc) * (T(1) + uc)) - t * uc;  // sin t - t cos t without sin and cos of t
  }
  return std::fmax(T(0), T(2) * v / (T(3) * kPiT * kPiT));
}

// Legendre expansion coefficient A_k of Eq 3 (p = 1/(4 pi) sum A_k P_k), by Gauss-Legendre
// quadrature (exact to ~1e-13 for k <= 40). A_0 = 1, A_1 = -4/3 (g = A_1 / 3 = -4/9), A_2 = 5/16.
double lambert_sphere_legendre_coefficient(int k);

// Eq 6: exact sampling of the scattering cosine from three uniform numbers in [0, 1).
template <class T>
T sample_lambert_sphere_cosine_exact(T xi1, T xi2, T xi3) {
  constexpr T kTwoPi = T(6.28318530717958647692);
  return std::sqrt((T(1) - xi1) * (T(1) - xi2)) * std::sin(kTwoPi * xi3) - std::sqrt(xi1 * xi2);
}

// Eq 7: approximate inverse CDF from one uniform number (max |u - u_exact| ~ 5.7e-4, see tests).
template <class T>
T sample_lambert_sphere_cosine_approx(T xi) {
  const T inner = T(1) - std::pow(xi, T(0.0401885) * xi + T(1.01938));
  return T(1) - T(2) * std::pow(std::fmax(T(0), inner), T(0.397225));
}

// Exact cumulative distribution P(U <= u) = 2 pi * integral_{-1}^{u} p(t) dt in closed form (for tests
// and for checking Eq 7); derivation in the .cpp.
double lambert_sphere_cdf(double u);
// Exact inverse CDF by safeguarded Newton iteration on lambert_sphere_cdf (reference for Eq 7).
double lambert_sphere_inverse_cdf(double xi);

// The Legendre coefficients A_0..A_2 of the three-term LS phase function (d'Eon Eq 5) and of the
// full LS phase function up to order L: the input of the half-space solver
// (materials/numerics/halfspace_doubling.h).
std::vector<double> lambert_sphere_three_term_coefficients();
std::vector<double> lambert_sphere_coefficients(int max_order);

}  // namespace ochre
