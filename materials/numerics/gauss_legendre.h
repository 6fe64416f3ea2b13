#pragma once
// Gauss-Legendre quadrature rules on [-1, 1] (nodes ascending), computed by Newton iteration on
// P_n; exact for polynomials of degree 2n - 1. Used by the numerical checks and tabulations of the
// Lambert-sphere model (H functions, half-space doubling).

#include <vector>

namespace ochre {

struct GaussLegendreRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

GaussLegendreRule gauss_legendre_rule(int n);

// The same rule mapped to [a, b].
GaussLegendreRule gauss_legendre_rule(int n, double a, double b);

}  // namespace ochre
