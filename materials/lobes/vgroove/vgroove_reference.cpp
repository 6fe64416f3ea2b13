#include "materials/lobes/vgroove/vgroove_reference.h"

#include <cmath>
#include <numbers>

#include "materials/numerics/gauss_legendre.h"

namespace ochre {

Vec3d groove_direction(double theta, double phi) {
  return {std::sin(theta) * std::sin(phi), std::sin(theta) * std::cos(phi), std::cos(theta)};
}

DirectionalReflectance directional_reflectance(const VGroove& groove, const Vec3d& e, ChainModel model,
                                               std::span<const FacetIndex> facets, int reflection_limit) {
  DirectionalReflectance out;
  out.reflectance.assign(facets.size(), 0.0);
  const std::vector<double> y = groove.breakpoints(e);
  std::vector<ChainResponse> responses;
  responses.reserve(facets.size());
  for (size_t i = 0; i + 1 < y.size(); ++i) {
    const double width = y[i + 1] - y[i];
    if (!(width > 0.0)) continue;
    const VGroovePath path = groove.trace(e, 0.5 * (y[i] + y[i + 1]));
    out.max_reflections = std::max(out.max_reflections, path.reflections);
    if (reflection_limit > 0 && path.reflections > reflection_limit) continue;
    responses.clear();
    for (const FacetIndex& f : facets) responses.emplace_back(model, f);
    light_chain(groove, path, [&](const ChainStep& step) {
      for (ChainResponse& r : responses) r.add(step);
    });
    for (size_t k = 0; k < facets.size(); ++k) out.reflectance[k] += width * responses[k].reflectance();
  }
  const double opening = 2.0 * groove.half_opening();
  for (double& r : out.reflectance) r /= opening;
  return out;
}

std::vector<double> bihemispherical_reflectance(const VGroove& groove, ChainModel model,
                                                std::span<const FacetIndex> facets, int reflection_limit,
                                                int quadrature_points) {
  // With u = sin^2 theta, cos(theta) sin(theta) dtheta = du / 2, so
  // (1/pi) int_0^2pi int_0^pi/2 R cos sin dtheta dphi = (4/pi) int_0^pi/2 dphi int_0^1 R du / 2.
  const GaussLegendreRule us = gauss_legendre_rule(quadrature_points, 0.0, 1.0);
  const GaussLegendreRule phis = gauss_legendre_rule(quadrature_points, 0.0, 0.5 * std::numbers::pi);
  std::vector<double> total(facets.size(), 0.0);
  for (size_t a = 0; a < us.nodes.size(); ++a) {
    const double theta = std::asin(std::sqrt(us.nodes[a]));
    for (size_t b = 0; b < phis.nodes.size(); ++b) {
      const DirectionalReflectance r = directional_reflectance(groove, groove_direction(theta, phis.nodes[b]),
                                                               model, facets, reflection_limit);
      const double w = us.weights[a] * phis.weights[b];
      for (size_t k = 0; k < facets.size(); ++k) total[k] += w * r.reflectance[k];
    }
  }
  for (double& t : total) t *= 2.0 / std::numbers::pi;
  return total;
}

}  // namespace ochre
