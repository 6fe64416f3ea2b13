#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"

#include <algorithm>
#include <cmath>

#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/numerics/halfspace_doubling.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

// Legendre order of the LS phase function in the doubling: A_l ~ l^-4, order 12 changes the
// multiple scattering by < 1e-5 of the BRDF relative to order 8.
constexpr int kLegendreOrder = 12;

}  // namespace

double LambertSphereExactGrid::mu(int i) const {
  const double x = double(i) / (x_nodes - 1);
  return std::max(1e-8, x * x * x);
}

double LambertSphereExactGrid::c(int s) const {
  const double v = double(s) / (s_nodes - 1);
  return 1.0 - v * v;
}

std::vector<float> compute_lambert_sphere_exact_slice(const LambertSphereExactGrid& grid, int s,
                                                      int quadrature_nodes) {
  static const std::vector<double> coefficients = lambert_sphere_coefficients(kLegendreOrder);
  std::vector<double> mus(grid.x_nodes);
  for (int i = 0; i < grid.x_nodes; ++i) mus[i] = grid.mu(i);
  HalfspaceDoublingOptions options;
  options.quadrature_nodes = quadrature_nodes;
  options.max_mode = LambertSphereExactGrid::kModes - 1;
  // The multiple scattering is O(c^2): tabulating it over c^2 keeps linear interpolation in s accurate
  // at low c (c = 0 itself is solved at c = 1e-4).
  const double c = std::max(1e-4, grid.c(s));
  const HalfspaceMultipleScattering ms = halfspace_multiple_scattering(coefficients, c, mus, options);
  std::vector<float> slice(LambertSphereExactGrid::kModes * grid.triangle());
  for (int m = 0; m < LambertSphereExactGrid::kModes; ++m)
    for (int i = 0; i < grid.x_nodes; ++i)
      for (int o = i; o < grid.x_nodes; ++o)
        slice[grid.index(0, m, i, o)] =
            float((mus[i] + mus[o]) * 0.5 * (ms.value(m, i, o) + ms.value(m, o, i)) / (c * c));
  return slice;
}

std::vector<float> compute_lambert_sphere_exact_table(const LambertSphereExactGrid& grid,
                                                      int quadrature_nodes) {
  std::vector<float> table;
  table.reserve(grid.size());
  for (int s = 0; s < grid.s_nodes; ++s) {
    const std::vector<float> slice = compute_lambert_sphere_exact_slice(grid, s, quadrature_nodes);
    table.insert(table.end(), slice.begin(), slice.end());
  }
  return table;
}

LambertSphereExactConstants lambert_sphere_exact_constants(float c) {
  const LambertSphereExactGrid& grid = lambert_sphere_exact_grid();
  LambertSphereExactConstants k;
  k.c = nan_safe_clamp(c, 0.0f, 1.0f);  // NaN -> 0: c gives the index
  const float f = std::sqrt(1.0f - k.c) * float(grid.s_nodes - 1);
  k.s_index = std::min(int(f), grid.s_nodes - 2);
  k.s_weight = std::clamp(f - float(k.s_index), 0.0f, 1.0f);
  return k;
}

LambertSphereExactGeometry lambert_sphere_exact_geometry(float mu_i, float mu_o, float wi_dot_wo) {
  LambertSphereExactGeometry g;
  if (!(mu_i > 0.0f) || !(mu_o > 0.0f)) return g;
  const LambertSphereExactGrid& grid = lambert_sphere_exact_grid();
  g.valid = true;
  const float scale = float(grid.x_nodes - 1);
  const float fi = std::cbrt(std::min(mu_i, 1.0f)) * scale, fo = std::cbrt(std::min(mu_o, 1.0f)) * scale;
  g.i = std::min(int(fi), grid.x_nodes - 2);
  g.o = std::min(int(fo), grid.x_nodes - 2);
  g.ti = fi - float(g.i);
  g.to = fo - float(g.o);
  g.inv_sum = 1.0f / (mu_i + mu_o);
  // S^m cos(m phi): S cos(phi) = wi.wo - mu_i mu_o; S^2 cos(2 phi) = 2 (S cos phi)^2 - S^2.
  const float s_cos = wi_dot_wo - mu_i * mu_o;
  const float s2 = std::max(0.0f, (1.0f - mu_i * mu_i) * (1.0f - mu_o * mu_o));
  g.harmonic[0] = 1.0f;
  g.harmonic[1] = s_cos;
  g.harmonic[2] = 2.0f * s_cos * s_cos - s2;
  g.phase_over_sum = lambert_sphere_phase(-wi_dot_wo) * g.inv_sum;
  return g;
}

float lambert_sphere_exact_multiple_scattering(const LambertSphereExactConstants& k,
                                               const LambertSphereExactGeometry& g) {
  if (!g.valid) return 0.0f;
  const LambertSphereExactGrid& grid = lambert_sphere_exact_grid();
  const float* data = lambert_sphere_exact_data();
  float sum = 0.0f;
  for (int ds = 0; ds < 2; ++ds) {
    const int s = k.s_index + ds;
    const float ws = ds ? k.s_weight : 1.0f - k.s_weight;
    if (ws == 0.0f) continue;
    for (int m = 0; m < LambertSphereExactGrid::kModes; ++m) {
      const float v00 = data[grid.index(s, m, g.i, g.o)], v01 = data[grid.index(s, m, g.i, g.o + 1)];
      const float v10 = data[grid.index(s, m, g.i + 1, g.o)], v11 = data[grid.index(s, m, g.i + 1, g.o + 1)];
      const float bilinear =
          (1.0f - g.ti) * ((1.0f - g.to) * v00 + g.to * v01) + g.ti * ((1.0f - g.to) * v10 + g.to * v11);
      sum += ws * g.harmonic[m] * bilinear;
    }
  }
  // The table holds (mu_i + mu_o) f_ms^(m) / (c^2 S^m).
  return k.c * k.c * sum * g.inv_sum;
}

float lambert_sphere_exact(const LambertSphereExactConstants& k, const LambertSphereExactGeometry& g) {
  if (!g.valid) return 0.0f;
  return std::max(0.0f, k.c * g.phase_over_sum + lambert_sphere_exact_multiple_scattering(k, g));
}

float lambert_sphere_exact_multiple_scattering(const LambertSphereExactConstants& k, float mu_i, float mu_o,
                                               float wi_dot_wo) {
  return lambert_sphere_exact_multiple_scattering(k, lambert_sphere_exact_geometry(mu_i, mu_o, wi_dot_wo));
}

float lambert_sphere_exact(const LambertSphereExactConstants& k, float mu_i, float mu_o, float wi_dot_wo) {
  return lambert_sphere_exact(k, lambert_sphere_exact_geometry(mu_i, mu_o, wi_dot_wo));
}

double lambert_sphere_exact_bond_albedo(double c) {
  const LambertSphereExactConstants k = lambert_sphere_exact_constants(float(c));
  return bond_albedo_quadrature(
      [&](double a, double b, double w) { return lambert_sphere_exact(k, float(a), float(b), float(w)); });
}

const BondAlbedoInverse& lambert_sphere_exact_kd_inverse() {
  static const BondAlbedoInverse inverse(lambert_sphere_exact_bond_albedo);
  return inverse;
}

}  // namespace ochre
