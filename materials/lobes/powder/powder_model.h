#pragma once
// The dry-powder BRDF of Gerardin, Martinetto and Holzschuch 2023 ("Dry powders reflectance model based
// on enhanced back-scattering: case of hematite alpha-Fe2O3", Optics Express), as pure math:
//
//   f(wi, wo, lambda) = A_v [L1 + L2 + C] + A_s' S
//
// L1 single scattering (Eq 14a, Henyey-Greenstein phase function, cos Theta = -wi.wo), L2 the multiple-
// scattering ladder (Eq 21 with its sign fixed, in its symmetric form, decaying with c0), C the cyclical
// term that makes the enhanced backscattering peak (Eq 25), S the Harvey-Shack surface term (Eqs 27-28
// with A_s' = A_s sigma_s^2). L2 and C are divided by 4 pi so that every term is a true BRDF in 1/sr.
// Every decision (and the printed variants kept as options for comparison) is in docs/materials/powder.md.
//
// Local frame: z is the normal, wi towards the light, wo towards the viewer, both unit; the BRDF is 0
// unless both are above the surface. Lengths in micrometres. Templated on the float type: the renderer
// evaluates in float, the tests and tools in double.

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ochre {

// Options; the defaults are the model of docs/materials/powder.md, the others the printed paper.
enum class PowderLadder { kSymmetric, kPrinted };            // Eq 21 sign-fixed (symmetric form) / as printed
enum class PowderLadderDecay { kC0, kWithAlpha };            // the ladder's c: c0, or Eq 22's c with alpha
enum class PowderNormalisation { kPerSteradian, kPrinted };  // L2, C divided by 4 pi, or as printed
enum class PowderSurface { kHarveyShack, kGaussian };        // Eqs 27-28, or Eq 26

template <class T>
struct PowderParams {
  T volume_amplitude = 1;         // A_v
  T g = 0;                        // Henyey-Greenstein anisotropy, (-1, 1)
  T kappa = T(0.25);              // extinction coefficient, 1/um
  T surface_amplitude = T(3e-6);  // A_s' = A_s sigma_s^2, um^2
  T correlation_length = 2;       // l_c, um
  T thickness = T(1e30);          // d, um (1e30: infinite)
  T gaussian_sigma = T(0.1);      // Eq 26 only: the Gaussian's width in radians
  PowderLadder ladder = PowderLadder::kSymmetric;
  PowderLadderDecay ladder_decay = PowderLadderDecay::kC0;
  PowderNormalisation normalisation = PowderNormalisation::kPerSteradian;
  PowderSurface surface = PowderSurface::kHarveyShack;
};

// What the model needs at one wavelength.
template <class T>
struct PowderWavelength {
  T lambda_um = T(0.7);
  T rho = T(0.752);     // single-scattering albedo of the grains
  T tau_o = T(0.0318);  // extrapolation ratio of Eq 16
};

template <class T>
struct PowderTerms {
  T l1 = 0, l2 = 0, c = 0, s = 0;
  T volume() const { return l1 + l2 + c; }
};

namespace powder_detail {

// E(x) = (1 - exp(-2 x tau)) / x, with its limit 2 tau at x = 0.
template <class T>
T exit_factor(T x, T tau) {
  const T t = 2 * x * tau;
  if (t < T(1e-4)) return 2 * tau * (1 - t * (T(0.5) - t / 6));
  return -std::expm1(-t) / x;
}

// Henyey-Greenstein phase function normalised over the sphere (Eq 12).
template <class T>
T henyey_greenstein(T cos_theta, T g) {
  const T denom = 1 + g * g - 2 * g * cos_theta;
  return (1 - g * g) / (4 * std::numbers::pi_v<T> * denom * std::sqrt(denom));
}

}  // namespace powder_detail

// The four terms (before the amplitudes A_v and A_s') at one wavelength.
template <class T, class V>
PowderTerms<T> powder_terms(const PowderParams<T>& p, const PowderWavelength<T>& w, const V& wi,
                            const V& wo) {
  PowderTerms<T> out;
  const T mu_i = T(wi.z), mu_o = T(wo.z);
  if (!(mu_i > 0) || !(mu_o > 0)) return out;
  constexpr T kPi = std::numbers::pi_v<T>;
  const T dx_ebs = T(wo.x) - T(wi.x), dy_ebs = T(wo.y) - T(wi.y);
  const T f_ebs = std::sqrt(dx_ebs * dx_ebs + dy_ebs * dy_ebs);  // 0 at exact backscatter
  const T k_over_kappa = 2 * kPi / (w.lambda_um * p.kappa);      // k0 / kappa
  const T v = T(0.5) * (1 / mu_i + 1 / mu_o);
  const T u = k_over_kappa * (mu_i - mu_o);
  const T alpha = k_over_kappa * f_ebs;
  const T rho = w.rho;
  const T c0 = std::sqrt(std::max(T(0), 3 * (1 - rho) * (1 - rho * p.g)));
  const T c = std::sqrt(c0 * c0 + alpha * alpha);
  const T scale = p.normalisation == PowderNormalisation::kPerSteradian ? 1 / (4 * kPi) : T(1);

  // L1 (Eq 14a): single scattering, the thickness factor 1 for an infinite layer.
  const T cos_theta = -(T(wi.x) * T(wo.x) + T(wi.y) * T(wo.y) + mu_i * mu_o);
  // 1 - exp(-x) with x the optical depth through the layer: for x > 100 that is 1 exactly in float and double
  // (e^-100 = 4e-44), so the call is skipped there: an infinite layer (the default thickness 1e30) at every
  // evaluation.
  const T optical_depth = p.kappa * p.thickness * (1 / mu_i + 1 / mu_o);
  const T depth = optical_depth > T(100) ? T(1) : -std::expm1(-optical_depth);
  out.l1 = rho * powder_detail::henyey_greenstein(cos_theta, p.g) / (mu_i + mu_o) * depth;

  // L2: the ladder of Eq 21.
  const T cl = p.ladder_decay == PowderLadderDecay::kC0 ? c0 : c;
  if (p.ladder == PowderLadder::kSymmetric) {
    // 2Q / (1 + mu_o c) with Q of Eq 15e, in the symmetric form (reciprocal, no pole).
    out.l2 = scale * 3 * rho * rho * (1 + v * powder_detail::exit_factor(cl, w.tau_o)) /
             (2 * v * (1 + cl * mu_i) * (1 + cl * mu_o));
  } else {
    // As printed: 3 rho^2 / (1 - mu_i^2 c^2) [2Q / (1 - mu_o c) - mu_i^2 / (mu_i + mu_o)].
    const T q = (1 + mu_i * cl - (1 - mu_i * cl) * std::exp(-2 * cl * w.tau_o)) / (4 * cl);
    out.l2 = scale * 3 * rho * rho / (1 - mu_i * mu_i * cl * cl) *
             (2 * q / (1 - mu_o * cl) - mu_i * mu_i / (mu_i + mu_o));
  }

  // C (Eq 25): the cyclical term, the peak at backscatter.
  out.c = scale * 3 * rho * rho * (1 + v * powder_detail::exit_factor(c, w.tau_o)) /
          (2 * mu_i * mu_o * v * ((c + v) * (c + v) + u * u));

  // S: Harvey-Shack (Eqs 27-28) around the mirror direction, or the Gaussian of Eq 26.
  const T sx = T(wo.x) + T(wi.x), sy = T(wo.y) + T(wi.y);
  if (p.surface == PowderSurface::kHarveyShack) {
    const T f2 = (sx * sx + sy * sy) / (w.lambda_um * w.lambda_um);
    const T lc = p.correlation_length;
    const T l2 = w.lambda_um * w.lambda_um;
    out.s = 4 * kPi * kPi / (l2 * l2) * (mu_i + mu_o) * (mu_i + mu_o) * kPi * lc * lc *
            std::exp(-kPi * kPi * lc * lc * f2);
  } else {
    // theta: the angle between wo and the mirror direction of wi.
    const T cos_mirror = std::clamp(-T(wi.x) * T(wo.x) - T(wi.y) * T(wo.y) + mu_i * mu_o, T(-1), T(1));
    const T theta = std::acos(cos_mirror), sigma = p.gaussian_sigma;
    out.s = std::exp(-theta * theta / (2 * sigma * sigma)) / (sigma * std::sqrt(2 * kPi));
  }
  return out;
}

// The BRDF (1/sr).
template <class T, class V>
T powder_brdf(const PowderParams<T>& p, const PowderWavelength<T>& w, const V& wi, const V& wo) {
  const PowderTerms<T> t = powder_terms(p, w, wi, wo);
  return p.volume_amplitude * t.volume() + p.surface_amplitude * t.s;
}

}  // namespace ochre
