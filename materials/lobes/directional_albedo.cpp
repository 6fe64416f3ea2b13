#include "materials/lobes/directional_albedo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "materials/core/pcg32.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre {

namespace {

// Gauss-Legendre in cos theta on each hemisphere separately (f usually has a kink or a jump at the
// horizon) times the midpoint rule in phi (periodic, so it converges fast).
double quadrature_albedo(const Closure& closure, const Vec3& wo, const SampledWavelengths& lambda,
                         int mu_nodes, int phi_nodes) {
  const GaussLegendreRule rule = gauss_legendre_rule(mu_nodes, 0.0, 1.0);
  const double dphi = 2.0 * std::numbers::pi / phi_nodes;
  double sum = 0.0;
  for (double hemisphere : {1.0, -1.0})
    for (int i = 0; i < mu_nodes; ++i) {
      const double mu = hemisphere * rule.nodes[i], sin_theta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
      double ring = 0.0;
      for (int j = 0; j < phi_nodes; ++j) {
        const double phi = (j + 0.5) * dphi;
        const Vec3 wi{static_cast<float>(sin_theta * std::cos(phi)),
                      static_cast<float>(sin_theta * std::sin(phi)), static_cast<float>(mu)};
        ring += closure.eval(wo, wi, lambda)[0];
      }
      sum += rule.weights[i] * rule.nodes[i] * ring * dphi;
    }
  return sum;
}

}  // namespace

AlbedoEstimate directional_albedo(const Closure& closure, const Vec3& wo, const SampledWavelengths& lambda,
                                  uint64_t samples, uint64_t seed, const std::function<bool()>& stop) {
  AlbedoEstimate r;
  Pcg32 rng(seed);
  double sum = 0.0, sum_squares = 0.0;
  for (uint64_t k = 0; k < samples; ++k) {
    if (stop && (k & 0xffff) == 0xffff && stop()) return r;
    const float u_choice = rng.next_float();
    const Vec2 u{rng.next_float(), rng.next_float()};
    const std::optional<LobeSample> s = closure.sample(wo, u_choice, u, lambda);
    const double x = s ? s->weight[0] : 0.0;
    sum += x;
    sum_squares += x * x;
  }
  if (samples > 0) {
    r.monte_carlo = sum / samples;
    const double variance =
        samples > 1 ? (sum_squares / samples - r.monte_carlo * r.monte_carlo) * samples / (samples - 1.0)
                    : 0.0;
    r.monte_carlo_se = std::sqrt(std::max(0.0, variance) / samples);
  }
  const double coarse = quadrature_albedo(closure, wo, lambda, 32, 64);
  r.quadrature = quadrature_albedo(closure, wo, lambda, 64, 128);
  r.quadrature_error = std::abs(r.quadrature - coarse);
  return r;
}

}  // namespace ochre
