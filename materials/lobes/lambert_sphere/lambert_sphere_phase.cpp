#include "materials/lobes/lambert_sphere/lambert_sphere_phase.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "materials/core/pi.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre {

namespace {

// Legendre polynomial P_k(x) by the three-term recurrence.
double legendre(int k, double x) {
  double p0 = 1.0, p1 = x;
  if (k == 0) return p0;
  for (int l = 2; l <= k; ++l) {
    const double p2 = ((2 * l - 1) * x * p1 - (l - 1) * p0) / l;
    p0 = p1;
    p1 = p2;
  }
  return p1;
}

// Antiderivative of sqrt(1 - t^2) - t acos(t): integrating t acos(t) by parts gives
// F(t) = 3/4 t sqrt(1 - t^2) + 1/4 asin(t) - t^2/2 acos(t); F(1) - F(-1) = 3 pi / 4.
double phase_antiderivative(double t) {
  const double r = std::sqrt(std::max(0.0, 1.0 - t * t));
  return 0.75 * t * r + 0.25 * std::asin(t) - 0.5 * t * t * std::acos(t);
}

}  // namespace

double lambert_sphere_legendre_coefficient(int k) {
  // p has (1 -+ u)^(3/2) endpoint behaviour; u = cos(theta) makes the integrand smooth in theta.
  const GaussLegendreRule& rule = gauss_legendre_rule(96);
  double sum = 0.0;
  for (size_t i = 0; i < rule.nodes.size(); ++i) {
    const double theta = 0.5 * kPiD * (rule.nodes[i] + 1.0);
    const double u = std::cos(theta);
    sum += rule.weights[i] * lambert_sphere_phase(u) * legendre(k, u) * std::sin(theta);
  }
  return 2.0 * kPiD * (2 * k + 1) * sum * 0.5 * kPiD;
}

double lambert_sphere_cdf(double u) {
  u = std::clamp(u, -1.0, 1.0);
  // 2 pi * 2 / (3 pi^2) = 4 / (3 pi); F(-1) = -5 pi / 8.
  return std::clamp(4.0 / (3.0 * kPiD) * (phase_antiderivative(u) + 5.0 * kPiD / 8.0), 0.0, 1.0);
}

double lambert_sphere_inverse_cdf(double xi) {
  double lo = -1.0, hi = 1.0, u = 1.0 - 2.0 * std::pow(1.0 - xi, 0.4);  // near Eq 7
  for (int it = 0; it < 100; ++it) {
    const double f = lambert_sphere_cdf(u) - xi;
    if (f > 0.0)
      hi = u;
    else
      lo = u;
    const double slope = 2.0 * kPiD * lambert_sphere_phase(u);
    double next = slope > 0.0 ? u - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::fabs(next - u) < 1e-15) return next;
    u = next;
  }
  return u;
}

std::vector<double> lambert_sphere_three_term_coefficients() {
  return {1.0, -4.0 / 3.0, 5.0 / 16.0};
}

std::vector<double> lambert_sphere_coefficients(int max_order) {
  std::vector<double> A(max_order + 1);
  for (int l = 0; l <= max_order; ++l) A[l] = lambert_sphere_legendre_coefficient(l);
  return A;
}

}  // namespace ochre
