#include "materials/lobes/powder/powder_optics.h"

#include <cmath>
#include <complex>
#include <numbers>

#include "materials/lobes/fresnel.h"
#include "materials/numerics/gauss_legendre.h"
#include "materials/numerics/mie.h"

namespace ochre {

double internal_fresnel_moment(double n, int i) {
  // Inside the grain the relative index of air is 1 / n; below mu_c every ray is totally reflected.
  const double mu_c = n > 1.0 ? std::sqrt(1.0 - 1.0 / (n * n)) : 0.0;
  double sum = 0.0;
  // [0, mu_c]: R_F = 1, so the integral is exact: mu_c^(i+1) / (i + 1).
  sum += std::pow(mu_c, i + 1) / (i + 1);
  // [mu_c, 1]: the Fresnel reflectance, smooth there; 64 points give 1e-12.
  const GaussLegendreRule rule = gauss_legendre_rule(64, mu_c, 1.0);
  for (size_t j = 0; j < rule.nodes.size(); ++j) {
    const double mu = rule.nodes[j];
    const FresnelAmplitudes<double> a = fresnel_amplitudes_dielectric(mu, 1.0 / n);
    const double r = 0.5 * (std::norm(a.r_s) + std::norm(a.r_p));
    sum += rule.weights[j] * r * std::pow(mu, i);
  }
  return sum;
}

double powder_tau_o(double n, PowderTau model) {
  if (model == PowderTau::kTwoThirds) return 2.0 / 3.0;
  const double c1 = internal_fresnel_moment(n, 1), c2 = internal_fresnel_moment(n, 2);
  const double r = (3.0 * c2 + 2.0 * c1) / (3.0 * c2 - 2.0 * c1 + 2.0);
  if (model == PowderTau::kZhuPineWeitz) return 2.0 / 3.0 * (1.0 + r) / (1.0 - r);
  return 2.0 / 3.0 * (1.0 - r) / (1.0 + r);
}

double grain_albedo(double n, double k, double radius_um, double lambda_um) {
  const double x = 2.0 * std::numbers::pi * radius_um / lambda_um;
  return mie_efficiencies({n, k}, x).albedo();
}

}  // namespace ochre
