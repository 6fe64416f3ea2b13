#pragma once
// The Lambertian-sphere (LS) BRDF of d'Eon ("An analytic BRDF for materials with spherical
// Lambertian scatterers"): a half space of sparse white-Lambertian spheres of albedo c.
//
//   f = f1 + f_m^(0) + f_m^(1) cos(phi)                                           (Eq 18)
//   f1 = c p(-wi.wo) / (mu_i + mu_o), p the exact LS phase function               (Eq 17)
//   f_m^(k) = f^(k) - f1^(k): the three-term half-space mode minus its own single scattering.
//
// Errata applied (evidence in docs/materials/lambert_sphere.md and tests/materials/lobes/lambert_sphere):
// - Eq 34: f1^(1) = c (45 mu_i mu_o + 64) S / (192 pi (mu_i + mu_o)) (printed: 384 pi);
// - Eq 27: f^(1) prefactor c H1 H1 / (3 pi (mu_i + mu_o)) (printed: 6 pi);
// - Eqs 28-30: H1(mu; c) = exp(ln H1(1; c) mu^q(mu)) with Eq 30's ln H1(1; c) and Eq 29's q.
// Conventions: wi, wo point away from the surface, mu = cos theta, no cosine factor in f; phi is
// the relative azimuth with phi = 0 when wi and wo are on the same side (backscatter), so
// S cos(phi) = wi.wo - mu_i mu_o with S = sqrt(1 - mu_i^2) sqrt(1 - mu_o^2). phi itself is never
// computed by the full model (it is 0/0 at S = 0). Every function returns 0 when mu_i <= 0 or
// mu_o <= 0.
//
// Everything that depends on c alone is in LambertSphereConstants: build it once per spectral
// sample (recomputing it per call costs ~50 % more); what depends on the directions alone is in
// LambertSphereGeometry, shared by the wavelengths of one evaluation.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <type_traits>

#include "materials/lobes/lambert_sphere/lambert_sphere_phase.h"
#include "materials/numerics/branchless_math.h"
#include "spectra/non_finite.h"

namespace ochre {

// exp, log and pow for the per-wavelength terms: in single precision the branchless ones, so the lobe's loops
// over the wavelengths vectorize; in double (the reference and tabulation paths) the library's.
template <class T>
T lambert_sphere_exp(T x) {
  if constexpr (std::is_same_v<T, float>)
    return branchless_exp(x);
  else
    return std::exp(x);
}

template <class T>
T lambert_sphere_log(T x) {
  if constexpr (std::is_same_v<T, float>)
    return branchless_log(x);
  else
    return std::log(x);
}

// x^p for x in [0, 1] and p > 0 (0^p is ~1e-37 rather than 0 in single precision).
template <class T>
T lambert_sphere_pow(T x, T p) {
  if constexpr (std::is_same_v<T, float>)
    return branchless_exp(p * branchless_log(x));
  else
    return std::pow(x, p);
}

template <class T>
struct LambertSphereConstants {
  T c = 0;
  // Zeroth mode (Eqs 36-42): H0 fit (Eq 37) and the polynomial constants.
  T h0_a = 0, h0_d = 0, inv_h0_infinity = 1;
  T A = 0, B = 0, C = 0, D = 0, E = 0, F = 0;
  // First mode (Eqs 27-32, corrected): ln H1(1; c) (Eq 30), l (Eq 31), l^2 + 45 m / 64 (Eq 32).
  T ln_h1_at_one = 0, l = 0, l2_plus_45m_over_64 = 0;
  // Fast variant (Eq 48): 0.234459 kd^1.85432 with kd from Eq 47, and 0.0151829 (c - 0.249978).
  T fast_constant = 0, fast_slope = 0;
};

// Eq 47: particle albedo c -> bond (spherical) albedo kd. Safe for c in [0, 1] (clamped).
template <class T>
T lambert_sphere_kd_from_c_eq47(T c) {
  const T s = std::sqrt(std::max(T(0), T(1) - nan_safe_clamp(c, T(0), T(1))));
  return std::clamp((T(1) - T(0.453029) * s * s - T(0.544162) * s) / (T(1.42931) * s + T(1)), T(0), T(1));
}

// Eq 46: kd -> c. kd and the result are clamped to [0, 1] (Eq 46 exceeds 1 for kd in [0.9988, 1)).
template <class T>
T lambert_sphere_c_from_kd_eq46(T kd) {
  const T q = T(1) - nan_safe_clamp(kd, T(0), T(1));
  return std::clamp((T(1) - std::pow(q, T(2.73556))) / (T(1) - T(0.184096) * std::pow(q, T(2.48423))), T(0),
                    T(1));
}

// The c-dependent constants (c clamped to [0, 1]).
// with_fast_variant = false leaves fast_constant (which only the fast variant reads, Eq 48) at 0.
template <class T>
LambertSphereConstants<T> lambert_sphere_constants(T c_in, bool with_fast_variant = true) {
  LambertSphereConstants<T> k;
  const T c = nan_safe_clamp(c_in, T(0), T(1));
  const T one_minus_c = T(1) - c, s = std::sqrt(one_minus_c), s3 = one_minus_c * s;
  k.c = c;
  // Eq 37 constants; 1/H0(inf) = sqrt(K0(0)) = sqrt((16 - c)(1 - c)(4c + 9)) / 12, finite at c = 1.
  const T s2 = s * s, s7 = s2 * s2 * s2 * s;
  k.h0_a = (T(1.50112) * lambert_sphere_pow(s, T(6.05435)) + T(8.21644)) / (T(4.17593) - T(1.21222) * s);
  k.h0_d = (T(7.7731) - T(0.565811) * lambert_sphere_pow(s, T(0.961546))) / (T(8.65912) - T(0.159974) * s7);
  k.inv_h0_infinity = std::sqrt(std::max(T(0), (T(16) - c) * one_minus_c * (T(4) * c + T(9)))) / T(12);
  // Eqs 38-42.
  k.A = T(69) * c / T(128);
  k.E = T(15) / T(128) * one_minus_c * c * (T(4) * c / T(3) + T(3));
  k.B = (T(0.346689) * s3 - T(0.777574) * one_minus_c + T(0.515357) * s - T(0.084463)) /
        (T(0.182602) * one_minus_c - T(0.665502) * s + T(0.964893));
  k.C = (T(-5602.45) * s3 + T(7487.99) * one_minus_c - T(2567.74) * s + T(682.848)) /
        (T(1480.25) * one_minus_c - T(4008.33) * s + T(5850.6));
  k.D = (T(166.883) * s3 - T(327.428) * one_minus_c + T(160.397) * s + T(0.285529)) /
        (T(596.423) * one_minus_c - T(412.984) * s + T(674.191));
  k.F = (T(266.063) * s3 - T(21.9141) * one_minus_c - T(242.16) * s - T(1.9209)) /
        (T(215.773) * one_minus_c + T(457.42) * s + T(1499.9));
  // Eqs 30-32.
  k.ln_h1_at_one = T(0.0242851) * c * c - T(0.144839) * c;
  k.l = T(-0.00473696) * c * c - T(0.0589037) * c;
  const T m = T(0.44038) * c + T(1);
  k.l2_plus_45m_over_64 = k.l * k.l + T(45) * m / T(64);
  // Eq 48.
  if (with_fast_variant)
    k.fast_constant = T(0.234459) * lambert_sphere_pow(lambert_sphere_kd_from_c_eq47(c), T(1.85432));
  k.fast_slope = T(0.0151829) * (c - T(0.249978));
  return k;
}

// Eq 37 in the safe form (1 + x) / (1 + x / H0(inf)), x = a mu^d.
template <class T>
T lambert_sphere_h0_fit(const LambertSphereConstants<T>& k, T mu) {
  const T x = k.h0_a * std::pow(std::max(mu, T(0)), k.h0_d);
  return (T(1) + x) / (T(1) + x * k.inv_h0_infinity);
}

// Eq 29's exponent q(mu).
template <class T>
T lambert_sphere_h1_exponent(T mu) {
  return ((T(-1.12831) * mu + T(1.85728)) * mu - T(1.07879)) * mu + T(0.459442);
}

// Corrected Eqs 28-30: H1(mu; c) = exp(ln H1(1; c) mu^q(mu)); H1(0) = 1, H1(1) = Eq 30.
template <class T>
T lambert_sphere_h1_fit(const LambertSphereConstants<T>& k, T mu) {
  mu = std::max(mu, T(0));
  return std::exp(k.ln_h1_at_one * std::pow(mu, lambert_sphere_h1_exponent(mu)));
}

// Eqs 28-30 as printed (for the tests that measure the erratum): H1(1; c) exp(-0.0894878 mu^q).
template <class T>
T lambert_sphere_h1_fit_as_printed(const LambertSphereConstants<T>& k, T mu) {
  mu = std::max(mu, T(0));
  return std::exp(k.ln_h1_at_one) * std::exp(T(-0.0894878) * std::pow(mu, lambert_sphere_h1_exponent(mu)));
}

// Everything that depends on the directions only, shared by the wavelengths of one evaluation
// (the phase function, the logarithms behind mu^d and mu^q, the polynomial terms).
template <class T>
struct LambertSphereGeometry {
  bool valid = false;  // mu_i > 0 and mu_o > 0
  T sum = 0, prod = 0, sq = 0, inv_sum = 0;
  T s_cos_phi = 0;       // S cos(phi) = wi.wo - mu_i mu_o
  T phase_over_sum = 0;  // p(-wi.wo) / (mu_i + mu_o): Eq 17 without c
  T log_mu_i = 0, log_mu_o = 0;
  T q_i = 0, q_o = 0;  // Eq 29's exponents
  // mu_i^q_i + mu_o^q_o, the exponent sum of H1(mu_i) H1(mu_o) (Eq 29) that does not depend on c: computed
  // once per direction pair, not once per wavelength.
  T h1_exponent_sum = 0;
};

// The polynomial and phase terms only (no logarithms or exponentials): all the fast variant reads.
template <class T>
LambertSphereGeometry<T> lambert_sphere_phase_geometry(T mu_i, T mu_o, T wi_dot_wo) {
  LambertSphereGeometry<T> g;
  if (!(mu_i > T(0)) || !(mu_o > T(0))) return g;
  g.valid = true;
  g.sum = mu_i + mu_o;
  g.prod = mu_i * mu_o;
  g.sq = mu_i * mu_i + mu_o * mu_o;
  g.inv_sum = T(1) / g.sum;
  g.s_cos_phi = wi_dot_wo - g.prod;
  g.phase_over_sum = lambert_sphere_phase(-wi_dot_wo) * g.inv_sum;
  return g;
}

template <class T>
LambertSphereGeometry<T> lambert_sphere_geometry(T mu_i, T mu_o, T wi_dot_wo) {
  LambertSphereGeometry<T> g = lambert_sphere_phase_geometry(mu_i, mu_o, wi_dot_wo);
  if (!g.valid) return g;
  g.log_mu_i = lambert_sphere_log(mu_i);
  g.log_mu_o = lambert_sphere_log(mu_o);
  g.q_i = lambert_sphere_h1_exponent(mu_i);
  g.q_o = lambert_sphere_h1_exponent(mu_o);
  g.h1_exponent_sum = lambert_sphere_exp(g.q_i * g.log_mu_i) + lambert_sphere_exp(g.q_o * g.log_mu_o);
  return g;
}

// Eq 17 with the exact phase function: c p(-wi.wo) / (mu_i + mu_o).
template <class T>
T lambert_sphere_single_scattering(T c, T mu_i, T mu_o, T wi_dot_wo) {
  if (!(mu_i > T(0)) || !(mu_o > T(0))) return T(0);
  return c * lambert_sphere_phase(-wi_dot_wo) / (mu_i + mu_o);
}

// Multiple scattering f_m^(0) + f_m^(1) cos(phi) of the corrected fitted model (Eqs 27-45) for valid
// geometry (mu_i, mu_o > 0): straight-line arithmetic, so loops over wavelengths vectorize.
template <class T>
T lambert_sphere_multiple_scattering_valid(const LambertSphereConstants<T>& k,
                                           const LambertSphereGeometry<T>& g) {
  constexpr T kPiT = T(3.14159265358979323846);
  // Eq 36 minus Eq 44; H0 of Eq 37 with mu^d = exp(d log mu).
  auto h0 = [&](T log_mu) {
    const T x = k.h0_a * lambert_sphere_exp(k.h0_d * log_mu);
    return (T(1) + x) / (T(1) + x * k.inv_h0_infinity);
  };
  const T poly0 =
      k.A + k.B * g.sum + k.C * g.prod + k.D * g.prod * g.sum + k.E * g.prod * g.prod + k.F * g.sq;
  const T f0 = h0(g.log_mu_i) * h0(g.log_mu_o) * poly0 / (T(2) * kPiT);
  const T f0_single =
      k.c * (T(207) + T(135) * g.prod * g.prod - T(45) * g.sq + T(256) * g.prod) / (T(768) * kPiT);
  // Corrected Eq 27 minus corrected Eq 34, both divided by S; times S cos(phi). H1 H1 in one exp.
  const T h1h1 = lambert_sphere_exp(k.ln_h1_at_one * g.h1_exponent_sum);
  const T poly1 = T(1) + k.l2_plus_45m_over_64 * g.prod + k.l * g.sum;
  const T f1_over_s = k.c * h1h1 * poly1 / (T(3) * kPiT);
  const T f1_single_over_s = k.c * (T(45) * g.prod + T(64)) / (T(192) * kPiT);
  return (f0 - f0_single + (f1_over_s - f1_single_over_s) * g.s_cos_phi) * g.inv_sum;
}

template <class T>
T lambert_sphere_multiple_scattering(const LambertSphereConstants<T>& k, const LambertSphereGeometry<T>& g) {
  return g.valid ? lambert_sphere_multiple_scattering_valid(k, g) : T(0);
}

template <class T>
T lambert_sphere_multiple_scattering(const LambertSphereConstants<T>& k, T mu_i, T mu_o, T wi_dot_wo) {
  return lambert_sphere_multiple_scattering(k, lambert_sphere_geometry(mu_i, mu_o, wi_dot_wo));
}

// The full model, Eq 18 (corrected), clamped at 0 (a guard: the fitted multiple scattering can be
// slightly negative where it is tiny, e.g. at c = 0 the fitted constants leave a floor of ~5e-5).
template <class T>
T lambert_sphere_full_valid(const LambertSphereConstants<T>& k, const LambertSphereGeometry<T>& g) {
  return std::max(T(0), k.c * g.phase_over_sum + lambert_sphere_multiple_scattering_valid(k, g));
}

template <class T>
T lambert_sphere_full(const LambertSphereConstants<T>& k, const LambertSphereGeometry<T>& g) {
  return g.valid ? lambert_sphere_full_valid(k, g) : T(0);
}

template <class T>
T lambert_sphere_full(const LambertSphereConstants<T>& k, T mu_i, T mu_o, T wi_dot_wo) {
  return lambert_sphere_full(k, lambert_sphere_geometry(mu_i, mu_o, wi_dot_wo));
}

// The direction-dependent factor of Eq 48, (|phi| + sqrt(mu_i mu_o)) / (acos(S)/S + 0.113706), in the
// safe form S (|phi| + sqrt(mu_i mu_o)) / (acos(S) + 0.113706 S) (finite at S = 0, where phi is
// undefined and the factor is 0). |phi| in radians in [0, pi], phi = 0 backscatter.
template <class T>
T lambert_sphere_fast_factor(T mu_i, T mu_o, T wi_dot_wo) {
  const T si = std::sqrt(std::max(T(0), T(1) - mu_i * mu_i)),
          so = std::sqrt(std::max(T(0), T(1) - mu_o * mu_o));
  const T S = std::min(T(1), si * so);
  const T cos_phi = S > T(0) ? std::clamp((wi_dot_wo - mu_i * mu_o) / S, T(-1), T(1)) : T(1);
  return (std::acos(cos_phi) + std::sqrt(mu_i * mu_o)) * S / (std::acos(S) + T(0.113706) * S);
}

// The fast variant, Eq 48 (kd from Eq 47). Not energy conserving (albedo up to ~1.3 at c = 1).
template <class T>
T lambert_sphere_fast(const LambertSphereConstants<T>& k, const LambertSphereGeometry<T>& g, T fast_factor) {
  if (!g.valid) return T(0);
  return std::max(T(0), k.c * g.phase_over_sum + k.fast_constant + k.fast_slope * fast_factor);
}

template <class T>
T lambert_sphere_fast(const LambertSphereConstants<T>& k, T mu_i, T mu_o, T wi_dot_wo) {
  if (!(mu_i > T(0)) || !(mu_o > T(0))) return T(0);
  return lambert_sphere_fast(k, lambert_sphere_phase_geometry(mu_i, mu_o, wi_dot_wo),
                             lambert_sphere_fast_factor(mu_i, mu_o, wi_dot_wo));
}

// Albedo integrals of an isotropic BRDF f(mu_i, mu_o, wi.wo) by Gauss quadrature (cosines as mu = x^2,
// which smooths the 1/(mu_i + mu_o) corner; azimuth over [0, pi] as f is even in phi); ~1e-6 accurate
// for the LS models (tests compare with finer rules). Directional albedo at mu_i:
// int f mu_o d omega_o; bond (spherical) albedo: 2 int_0^1 directional(mu_i) mu_i d mu_i.
using IsotropicBrdf = std::function<double(double mu_i, double mu_o, double wi_dot_wo)>;
double directional_albedo_quadrature(const IsotropicBrdf& f, double mu_i);
double bond_albedo_quadrature(const IsotropicBrdf& f);

// The bond albedo of the full model, and its directional albedo.
double lambert_sphere_bond_albedo(double c);
double lambert_sphere_directional_albedo(double c, double mu_i);

// Inverse of a model's bond albedo kd(c), tabulated on a uniform grid of s = sqrt(1 - c) (kd is smooth
// in s, not in c near 1) and interpolated linearly: |kd(c(kd)) - kd| < 1e-4. Above the largest
// reachable bond albedo (the fitted full model loses 1.4 % at c = 1) c is 1 and weight_scale() is the
// factor kd / kd_max the lobe weight needs for the rendered bond albedo to equal kd (<= 1.014).
class BondAlbedoInverse {
 public:
  static constexpr int kNodes = 65;
  static constexpr int kSearchCells = 1024;  // over kd in [0, 1]: where the search for kd's node starts
  explicit BondAlbedoInverse(const std::function<double(double c)>& bond_albedo);
  float c(float kd) const;
  // c[i] = c(kd[i]) for every i (spans of equal sizes, else std::invalid_argument), bit for bit.
  void c(std::span<const float> kd, std::span<float> c) const;
  float weight_scale(float kd) const;
  double max_bond_albedo() const { return kd_[0]; }

 private:
  // The last node above kd, exactly as a binary search finds it.
  int node_above(double kd) const;

  std::array<double, kNodes> kd_{};  // at s_j = j / (kNodes - 1): decreasing in j
  // For kd in [j, j + 1) / kSearchCells: the last node above (j + 1) / kSearchCells, from which at most
  // search_steps_ steps up reach the last node above kd (a node or two per cell).
  std::array<uint8_t, kSearchCells + 1> cell_start_{};
  int search_steps_ = 0;
};

// kd -> c for the full (and fast) variant: inverts lambert_sphere_bond_albedo; built on first use
// (thread safe, ~30 ms).
const BondAlbedoInverse& lambert_sphere_kd_inverse();
inline float lambert_sphere_c_from_kd(float kd) {
  return lambert_sphere_kd_inverse().c(kd);
}

}  // namespace ochre
