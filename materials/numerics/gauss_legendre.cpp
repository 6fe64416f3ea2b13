#include "materials/numerics/gauss_legendre.h"

#include <cmath>

#include "materials/core/pi.h"

namespace ochre {

GaussLegendreRule gauss_legendre_rule(int n) {
  GaussLegendreRule r;
  r.nodes.resize(n);
  r.weights.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPiD * (i + 0.75) / (n + 0.5));  // Tricomi's initial guess
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int l = 2; l <= n; ++l) {
        const double p2 = ((2 * l - 1) * x * p1 - (l - 1) * p0) / l;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0;
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    r.nodes[i] = -x;
    r.nodes[n - 1 - i] = x;
    r.weights[i] = r.weights[n - 1 - i] = w;
  }
  return r;
}

GaussLegendreRule gauss_legendre_rule(int n, double a, double b) {
  GaussLegendreRule r = gauss_legendre_rule(n);
  for (int i = 0; i < n; ++i) {
    r.nodes[i] = 0.5 * (a + b) + 0.5 * (b - a) * r.nodes[i];
    r.weights[i] *= 0.5 * (b - a);
  }
  return r;
}

}  // namespace ochre
