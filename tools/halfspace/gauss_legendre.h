#pragma once
// Gauss-Legendre quadrature nodes and weights on [0, 1] (Newton's method on P_n from the Chebyshev
// guess), for reference integrals (the half-space tests, ochre-brdf's deterministic albedo).

#include <cmath>
#include <numbers>
#include <vector>

namespace ochre::halfspace {

struct QuadratureRule {
  std::vector<double> x, w;
};

inline QuadratureRule gauss_legendre_unit(int n) {
  QuadratureRule rule{std::vector<double>(n), std::vector<double>(n)};
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {  // k P_k = (2k - 1) z P_{k-1} - (k - 1) P_{k-2}
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      derivative = n * (z * p0 - p1) / (z * z - 1.0);
      const double step = p0 / derivative;
      z -= step;
      if (std::abs(step) < 1e-15) break;
    }
    rule.x[i] = 0.5 * (1.0 - z);
    rule.w[i] = 1.0 / ((1.0 - z * z) * derivative * derivative);  // 2 / ((1 - z^2) P_n'^2), halved
  }
  return rule;
}

}  // namespace ochre::halfspace
