#include "materials/lobes/fresnel.h"

#include <algorithm>
#include <cmath>

namespace ochre {

namespace {

using Complex = std::complex<double>;

// Every amplitude is computed in double (the float API rounds the result): written out, double complex
// arithmetic is faster than the library's guarded routines (complex division and csqrt, which calls
// hypot, were 17 % of a V-groove render and 10 % of a polarized gold-mirror render) and needs no guard
// here, since |z| stays within 1e-40..1e80 for any finite float index.

// 1 / z as conj(z) / |z|^2.
Complex reciprocal(Complex z) {
  return std::conj(z) * (1.0 / std::norm(z));
}

// The principal square root, with |z| as sqrt(x^2 + y^2).
Complex principal_sqrt(Complex z) {
  const double x = z.real(), y = z.imag();
  if (x == 0.0 && y == 0.0) return {0.0, y};
  const double t = std::sqrt((std::sqrt(x * x + y * y) + std::fabs(x)) / 2.0);
  if (x >= 0.0) return {t, y / (2.0 * t)};
  return {std::fabs(y) / (2.0 * t), std::copysign(t, y)};
}

// The transmitted cosine on the decaying branch Im(cos_t) <= 0 (see fresnel.h). The principal square
// root already lies there for eta = n - i k with k > 0; for a real eta under total internal reflection
// the argument is a negative real whose zero imaginary part may carry either sign, so the sign of the
// imaginary part is set explicitly.
Complex transmitted_cosine(double cos_i, Complex eta) {
  const Complex root = principal_sqrt(1.0 - (1.0 - cos_i * cos_i) * reciprocal(eta * eta));
  return {root.real(), -std::abs(root.imag())};
}

// Born & Wolf Eqs. 1.5.20-21 in the Verdet sign convention of fresnel.h.
FresnelAmplitudes<double> amplitudes(double cos_i, Complex eta, bool real_index) {
  FresnelAmplitudes<double> a;
  a.eta = std::sqrt(std::norm(eta));
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  if (eta == Complex(1)) {  // no interface: the formulas are 0/0 at grazing incidence
    a.r_s = a.r_p = 0;
    a.t_s = a.t_p = 1;
    a.cos_t = cos_i;
    return a;
  }
  if (std::norm(eta) < 1e-30) {  // |eta| < 1e-15
    // The limit eta -> 0 (n = k = 0, or NaN inputs made 0): 1 / eta^2 would overflow. eta cos_t -> -i sin_i
    // (the branch above), so r_s -> (cos_i + i sin_i) / (cos_i - i sin_i) and r_p -> -1: everything is
    // reflected and nothing crosses.
    const Complex e_i(cos_i, std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i)));
    a.r_s = e_i * reciprocal(std::conj(e_i));
    a.r_p = -1.0;
    a.t_s = a.t_p = 0;
    a.cos_t = 0;
    a.total_internal_reflection = real_index;
    return a;
  }
  a.cos_t = transmitted_cosine(cos_i, eta);
  const Complex inv_den_s = reciprocal(cos_i + eta * a.cos_t), inv_den_p = reciprocal(eta * cos_i + a.cos_t);
  a.r_s = (cos_i - eta * a.cos_t) * inv_den_s;
  a.r_p = (eta * cos_i - a.cos_t) * inv_den_p;
  a.total_internal_reflection = real_index && (1.0 - cos_i * cos_i) > eta.real() * eta.real();
  if (a.total_internal_reflection) {
    a.t_s = a.t_p = 0;  // an evanescent wave only: it carries no power across
  } else {
    a.t_s = 2.0 * cos_i * inv_den_s;
    a.t_p = 2.0 * cos_i * inv_den_p;
  }
  return a;
}

FresnelAmplitudes<double> dielectric_amplitudes(double cos_i, double eta) {
  if (cos_i < 0.0) {  // incident from the other side of the interface
    cos_i = -cos_i;
    eta = 1.0 / eta;
  }
  return amplitudes(cos_i, Complex(eta), true);
}

FresnelAmplitudes<float> narrowed(const FresnelAmplitudes<double>& a) {
  FresnelAmplitudes<float> f;
  f.r_s = std::complex<float>(a.r_s);
  f.r_p = std::complex<float>(a.r_p);
  f.t_s = std::complex<float>(a.t_s);
  f.t_p = std::complex<float>(a.t_p);
  f.cos_t = std::complex<float>(a.cos_t);
  f.eta = static_cast<float>(a.eta);
  f.total_internal_reflection = a.total_internal_reflection;
  return f;
}

}  // namespace

FresnelAmplitudes<float> fresnel_amplitudes(float cos_i, std::complex<float> eta) {
  return narrowed(amplitudes(cos_i, Complex(eta), false));
}
FresnelAmplitudes<double> fresnel_amplitudes(double cos_i, std::complex<double> eta) {
  return amplitudes(cos_i, eta, false);
}
FresnelAmplitudes<float> fresnel_amplitudes_dielectric(float cos_i, float eta) {
  return narrowed(dielectric_amplitudes(cos_i, eta));
}
FresnelAmplitudes<double> fresnel_amplitudes_dielectric(double cos_i, double eta) {
  return dielectric_amplitudes(cos_i, eta);
}

// Real arithmetic (the hot path of the unpolarized renderer): the same amplitudes as above.
float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, -1.0f, 1.0f);
  if (cos_i < 0.0f) {
    cos_i = -cos_i;
    eta = 1.0f / eta;
  }
  if (eta == 1.0f) return 0.0f;
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;  // total internal reflection
  const float cos_t = std::sqrt(1.0f - sin2_t);
  const float r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const float r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5f * (r_s * r_s + r_p * r_p);
}

float fresnel_conductor(float cos_i, float n, float k) {
  const FresnelAmplitudes<float> a = fresnel_amplitudes(cos_i, std::complex<float>(n, -k));
  return 0.5f * (std::norm(a.r_s) + std::norm(a.r_p));
}

SampledSpectrum fresnel_conductor(float cos_i, const SampledSpectrum& n, const SampledSpectrum& k) {
  SampledSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = fresnel_conductor(cos_i, n[i], k[i]);
  return out;
}

Mueller fresnel_reflection_mueller(std::complex<float> r_s, std::complex<float> r_p) {
  const float rs = std::norm(r_s), rp = std::norm(r_p);
  const std::complex<float> w = r_s * std::conj(r_p);  // c exp(-i Delta), Delta = arg r_p - arg r_s
  Mueller m;
  m(0, 0) = m(1, 1) = 0.5f * (rs + rp);
  m(0, 1) = m(1, 0) = 0.5f * (rs - rp);
  m(2, 2) = m(3, 3) = w.real();  //  c cos Delta
  m(2, 3) = w.imag();            // -c sin Delta
  m(3, 2) = -w.imag();           //  c sin Delta
  return m;
}

Mueller specular_reflection(float cos_i, float eta) {
  const FresnelAmplitudes<float> a = fresnel_amplitudes_dielectric(cos_i, eta);
  return fresnel_reflection_mueller(a.r_s, a.r_p);
}

Mueller specular_reflection(float cos_i, std::complex<float> eta) {
  const FresnelAmplitudes<float> a = fresnel_amplitudes(cos_i, eta);
  return fresnel_reflection_mueller(a.r_s, a.r_p);
}

Mueller specular_transmission(float cos_i, float eta) {
  const FresnelAmplitudes<float> a = fresnel_amplitudes_dielectric(cos_i, eta);
  if (a.total_internal_reflection) return Mueller{};
  // T = eta cos_t / cos_i |t|^2 written without the division, so grazing incidence gives 0, not 0/0:
  // eta cos_t / cos_i (2 cos_i)^2 / den^2 = 4 eta cos_i cos_t / den^2. Here t_s, t_p are real and
  // positive, so the lower block has no phase: c = sqrt(T_s T_p).
  const float cos_i_abs = std::fabs(cos_i), cos_t = a.cos_t.real(), eta_used = a.eta;
  const float den_s = cos_i_abs + eta_used * cos_t, den_p = eta_used * cos_i_abs + cos_t;
  const float ts = 4.0f * eta_used * cos_i_abs * cos_t / (den_s * den_s);
  const float tp = 4.0f * eta_used * cos_i_abs * cos_t / (den_p * den_p);
  Mueller m;
  m(0, 0) = m(1, 1) = 0.5f * (ts + tp);
  m(0, 1) = m(1, 0) = 0.5f * (ts - tp);
  m(2, 2) = m(3, 3) = std::sqrt(ts * tp);
  return m;
}

}  // namespace ochre
