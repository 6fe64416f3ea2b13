#include "materials/lobes/lambert_sphere/lambert_sphere.h"

#include <cmath>
#include <stdexcept>

#include "materials/core/pi.h"
#include "materials/numerics/gauss_legendre.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

// Quadrature sizes for the albedo integrals (converged to ~1e-6 for the LS models, see the tests).
constexpr int kMuNodes = 24;
constexpr int kPhiNodes = 16;

struct AlbedoRules {
  GaussLegendreRule mu = gauss_legendre_rule(kMuNodes, 0.0, 1.0);  // in x, mu = x^2
  GaussLegendreRule phi = gauss_legendre_rule(kPhiNodes, 0.0, kPiD);
};

const AlbedoRules& albedo_rules() {
  static const AlbedoRules rules;
  return rules;
}

}  // namespace

double directional_albedo_quadrature(const IsotropicBrdf& f, double mu_i) {
  if (!(mu_i > 0.0)) return 0.0;
  const AlbedoRules& r = albedo_rules();
  const double sin_i = std::sqrt(std::max(0.0, 1.0 - mu_i * mu_i));
  double sum = 0.0;
  for (size_t a = 0; a < r.mu.nodes.size(); ++a) {
    const double x = r.mu.nodes[a], mu_o = x * x, sin_o = std::sqrt(std::max(0.0, 1.0 - mu_o * mu_o));
    double azimuth = 0.0;
    for (size_t b = 0; b < r.phi.nodes.size(); ++b)
      azimuth += r.phi.weights[b] * f(mu_i, mu_o, mu_i * mu_o + sin_i * sin_o * std::cos(r.phi.nodes[b]));
    sum += r.mu.weights[a] * 2.0 * x * mu_o * 2.0 * azimuth;  // d mu = 2x dx; phi over [0, 2 pi]
  }
  return sum;
}

double bond_albedo_quadrature(const IsotropicBrdf& f) {
  const AlbedoRules& r = albedo_rules();
  double sum = 0.0;
  for (size_t a = 0; a < r.mu.nodes.size(); ++a) {
    const double x = r.mu.nodes[a], mu_i = x * x;
    sum += r.mu.weights[a] * 2.0 * x * 2.0 * mu_i * directional_albedo_quadrature(f, mu_i);
  }
  return sum;
}

double lambert_sphere_directional_albedo(double c, double mu_i) {
  const LambertSphereConstants<double> k = lambert_sphere_constants(c);
  return directional_albedo_quadrature(
      [&](double a, double b, double w) { return lambert_sphere_full(k, a, b, w); }, mu_i);
}

double lambert_sphere_bond_albedo(double c) {
  const LambertSphereConstants<double> k = lambert_sphere_constants(c);
  return bond_albedo_quadrature(
      [&](double a, double b, double w) { return lambert_sphere_full(k, a, b, w); });
}

BondAlbedoInverse::BondAlbedoInverse(const std::function<double(double c)>& bond_albedo) {
  for (int j = 0; j < kNodes; ++j) {
    const double s = double(j) / (kNodes - 1);
    kd_[j] = bond_albedo(1.0 - s * s);
  }
  // The last node above a value by a linear scan (kd_ decreases; 0 when none is above, as the search gives).
  auto last_node_above = [&](double kd) {
    int lo = 0;
    while (lo + 1 < kNodes - 1 && kd_[lo + 1] > kd) ++lo;
    return lo;
  };
  for (int cell = 0; cell <= kSearchCells; ++cell) {
    const int at_top = last_node_above(double(cell + 1) / kSearchCells);
    const int at_bottom = last_node_above(double(cell) / kSearchCells);
    cell_start_[cell] = static_cast<uint8_t>(at_top);
    search_steps_ = std::max(search_steps_, at_bottom - at_top);
  }
}

int BondAlbedoInverse::node_above(double kd) const {
  // kd in [0, 1] times a power of two is exact: the cell is floor(kd kSearchCells), its edges exact too.
  int lo = cell_start_[static_cast<int>(kd * kSearchCells)];
  for (int step = 0; step < search_steps_; ++step) lo += (lo + 1 < kNodes - 1 && kd_[lo + 1] > kd) ? 1 : 0;
  return lo;
}

float BondAlbedoInverse::c(float kd_in) const {
  float c_out = 0.0f;
  c(std::span<const float>(&kd_in, 1), std::span<float>(&c_out, 1));
  return c_out;
}

void BondAlbedoInverse::c(std::span<const float> kd_in, std::span<float> c_out) const {
  if (c_out.size() != kd_in.size())
    throw std::invalid_argument("BondAlbedoInverse::c: spans of different sizes");
  for (std::size_t i = 0; i < kd_in.size(); ++i) {
    const double kd = nan_safe_clamp(double(kd_in[i]), 0.0, 1.0);
    if (kd >= kd_[0]) {
      c_out[i] = 1.0f;
    } else if (kd <= kd_[kNodes - 1]) {
      c_out[i] = 0.0f;
    } else {
      // Between the last node above kd and the next (kd_ decreases), linearly in s.
      const int lo = node_above(kd);
      const double t = (kd_[lo] - kd) / (kd_[lo] - kd_[lo + 1]);
      const double s = (lo + t) / (kNodes - 1);
      c_out[i] = float(std::clamp(1.0 - s * s, 0.0, 1.0));
    }
  }
}

float BondAlbedoInverse::weight_scale(float kd) const {
  return kd > kd_[0] ? float(std::min(1.0, double(kd)) / kd_[0]) : 1.0f;
}

const BondAlbedoInverse& lambert_sphere_kd_inverse() {
  static const BondAlbedoInverse inverse(lambert_sphere_bond_albedo);
  return inverse;
}

}  // namespace ochre
