#include "materials/numerics/h_function.h"

#include <algorithm>
#include <cmath>

#include "materials/core/pi.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre {

namespace {

// J_k(t) = int_0^1 x^(2k) / (1 + t^2 x^2) dx for k = 0..2.
std::array<double, 3> moments(double t) {
  std::array<double, 3> j{};
  const double t2 = t * t;
  if (t < 0.5) {
    // Geometric series 1 / (1 + t^2 x^2) = sum (-t^2 x^2)^n, ratio <= 1/4: 40 terms reach 1e-24.
    for (int k = 0; k < 3; ++k) {
      double term = 1.0, sum = 0.0;
      for (int n = 0; n < 40; ++n) {
        sum += term / (2 * k + 2 * n + 1);
        term *= -t2;
      }
      j[k] = sum;
    }
    return j;
  }
  j[0] = std::atan(t) / t;
  for (int k = 1; k < 3; ++k) j[k] = (1.0 / (2 * k - 1) - j[k - 1]) / t2;  // amplifies errors <= 16x
  return j;
}

}  // namespace

Characteristic lambert_sphere_characteristic(int mode, double c) {
  Characteristic psi;
  if (mode == 0) {
    // Psi0 = c/384 (207 + (c(20c + 281) - 346) x^2 - 15 (c - 1)(4c + 9) x^4)
    psi.coefficients = {207.0 * c / 384.0, c * (c * (20.0 * c + 281.0) - 346.0) / 384.0,
                        -15.0 * c * (c - 1.0) * (4.0 * c + 9.0) / 384.0};
  } else if (mode == 1) {
    // Psi1 = -c/192 (x^2 - 1)(5 (4c + 9) x^2 - 64) = c/192 (-64 + (20c + 109) x^2 - (20c + 45) x^4)
    psi.coefficients = {-64.0 * c / 192.0, c * (20.0 * c + 109.0) / 192.0, -c * (20.0 * c + 45.0) / 192.0};
  } else {
    // Psi2 = 15c/256 (x^2 - 1)^2
    const double a = 15.0 * c / 256.0;
    psi.coefficients = {a, -2.0 * a, a};
  }
  return psi;
}

Characteristic isotropic_characteristic(double c) {
  Characteristic psi;
  psi.coefficients = {0.5 * c, 0.0, 0.0};
  return psi;
}

double h_dispersion(const Characteristic& psi, double t) {
  const std::array<double, 3> j = moments(std::fabs(t));
  double integral = 0.0;
  for (int k = 0; k < 3; ++k) integral += psi.coefficients[k] * j[k];
  return 1.0 - 2.0 * integral;
}

double h_dispersion_at_zero(const Characteristic& psi) {
  return 1.0 - 2.0 * (psi.coefficients[0] + psi.coefficients[1] / 3.0 + psi.coefficients[2] / 5.0);
}

double h_function(const Characteristic& psi, double mu) {
  if (!(mu > 0.0)) return 1.0;
  // ln H = -(1/pi) int_0^{pi/2} log K(tan(theta) / mu) d theta on panels [pi/2 r^(j+1), pi/2 r^j]
  // with r = 1/8 down to 4e-15 of pi/2, then one last panel to 0 (its contribution is O(1e-15 log)).
  // 16 Gauss nodes per panel agree with r = 1/2 (3x the cost) to 1e-8 relative.
  static const GaussLegendreRule rule = gauss_legendre_rule(16);
  auto log_k = [&](double theta) {
    return std::log(std::max(1e-300, h_dispersion(psi, std::tan(theta) / mu)));
  };
  double sum = 0.0;
  double hi = 0.5 * kPiD;
  constexpr int kPanels = 16;
  for (int panel = 0; panel <= kPanels; ++panel) {
    const double lo = panel == kPanels ? 0.0 : 0.125 * hi;
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (size_t i = 0; i < rule.nodes.size(); ++i)
      sum += rule.weights[i] * half * log_k(mid + half * rule.nodes[i]);
    hi = lo;
  }
  return std::exp(-sum / kPiD);
}

double lambert_sphere_h_exact(int mode, double mu, double c) {
  return h_function(lambert_sphere_characteristic(mode, c), mu);
}

double isotropic_h_exact(double mu, double c) {
  return h_function(isotropic_characteristic(c), mu);
}

double lambert_sphere_dispersion_closed_form(int mode, double c, double t) {
  const double t2 = t * t, t3 = t2 * t, t5 = t3 * t2, at = std::atan(t);
  if (mode == 0) {
    const double q = 15.0 * (c - 1.0) * (4.0 * c + 9.0);
    return 1.0 - c *
                     ((256.0 * c - 301.0) * t3 +
                      ((346.0 - c * (20.0 * c + 281.0)) * t2 - q + 207.0 * t2 * t2) * at + q * t) /
                     (192.0 * t5);
  }
  if (mode == 1) {
    return 1.0 - c *
                     ((40.0 * c + 282.0) * t3 - 3.0 * (t2 + 1.0) * (20.0 * c + 64.0 * t2 + 45.0) * at +
                      15.0 * (4.0 * c + 9.0) * t) /
                     (288.0 * t5);
  }
  return 1.0 - 5.0 * c * (3.0 * (t2 + 1.0) * (t2 + 1.0) * at - t * (5.0 * t2 + 3.0)) / (128.0 * t5);
}

}  // namespace ochre
