#include "materials/lobes/fresnel.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace ochre {

namespace {

// 1 / z. In double precision as conj(z) / |z|^2: the library's complex division guards against overflow
// with a slow out-of-line routine (a tenth of the time of a V-groove render, whose reflection chains run in
// double), which double does not need here: |z| stays within 1e-40..1e80 for any finite float input. In
// float, |z|^2 would overflow for the largest indices, so the library's division stays.
template <class T>
std::complex<T> reciprocal(std::complex<T> z) {
  if constexpr (std::is_same_v<T, double>) return std::conj(z) * (1.0 / std::norm(z));
  return T(1) / z;
}

// The principal square root. In double precision with |z| as sqrt(x^2 + y^2): the library's csqrt calls
// hypot, whose guard against overflow costs as much again and is not needed for these arguments.
template <class T>
std::complex<T> principal_sqrt(std::complex<T> z) {
  if constexpr (!std::is_same_v<T, double>) return std::sqrt(z);
  const T x = z.real(), y = z.imag();
  if (x == T(0) && y == T(0)) return {T(0), y};
  const T t = std::sqrt((std::sqrt(x * x + y * y) + std::fabs(x)) / T(2));
  if (x >= T(0)) return {t, y / (T(2) * t)};
  return {std::fabs(y) / (T(2) * t), std::copysign(t, y)};
}

// The transmitted cosine on the decaying branch Im(cos_t) <= 0 (see fresnel.h). The principal square
// root already lies there for eta = n - i k with k > 0; for a real eta under total internal reflection
// the argument is a negative real whose zero imaginary part may carry either sign, so the sign of the
// imaginary part is set explicitly.
template <class T>
std::complex<T> transmitted_cosine(T cos_i, std::complex<T> eta) {
  const std::complex<T> cos_t_sq = T(1) - (T(1) - cos_i * cos_i) * reciprocal(eta * eta);
  const std::complex<T> root = principal_sqrt(cos_t_sq);
  return {root.real(), -std::abs(root.imag())};
}

// Born & Wolf Eqs. 1.5.20-21 in the Verdet sign convention of fresnel.h.
template <class T>
FresnelAmplitudes<T> amplitudes(T cos_i, std::complex<T> eta, bool real_index) {
  FresnelAmplitudes<T> a;
  a.eta = std::is_same_v<T, double> ? std::sqrt(std::norm(eta)) : std::abs(eta);  // as principal_sqrt
  cos_i = std::clamp(cos_i, T(0), T(1));
  if (eta == std::complex<T>(1)) {  // no interface: the formulas are 0/0 at grazing incidence
    a.r_s = a.r_p = 0;
    a.t_s = a.t_p = 1;
    a.cos_t = cos_i;
    return a;
  }
  if (std::norm(eta) < T(1e-30)) {  // |eta| < 1e-15
    // The limit eta -> 0 (n = k = 0, or NaN inputs made 0): 1 / eta^2 would overflow. eta cos_t -> -i sin_i
    // (the branch above), so r_s -> (cos_i + i sin_i) / (cos_i - i sin_i) and r_p -> -1: everything is
    // reflected and nothing crosses.
    const std::complex<T> e_i(cos_i, std::sqrt(std::max(T(0), T(1) - cos_i * cos_i)));
    a.r_s = e_i / std::conj(e_i);
    a.r_p = T(-1);
    a.t_s = a.t_p = 0;
    a.cos_t = 0;
    a.total_internal_reflection = real_index;
    return a;
  }
  a.cos_t = transmitted_cosine(cos_i, eta);
  const std::complex<T> inv_den_s = reciprocal(cos_i + eta * a.cos_t),
                        inv_den_p = reciprocal(eta * cos_i + a.cos_t);
  a.r_s = (cos_i - eta * a.cos_t) * inv_den_s;
  a.r_p = (eta * cos_i - a.cos_t) * inv_den_p;
  a.total_internal_reflection = real_index && (T(1) - cos_i * cos_i) > eta.real() * eta.real();
  if (a.total_internal_reflection) {
    a.t_s = a.t_p = 0;  // an evanescent wave only: it carries no power across
  } else {
    a.t_s = T(2) * cos_i * inv_den_s;
    a.t_p = T(2) * cos_i * inv_den_p;
  }
  return a;
}

template <class T>
FresnelAmplitudes<T> dielectric_amplitudes(T cos_i, T eta) {
  if (cos_i < T(0)) {  // incident from the other side of the interface
    cos_i = -cos_i;
    eta = T(1) / eta;
  }
  return amplitudes<T>(cos_i, std::complex<T>(eta), true);
}

}  // namespace

FresnelAmplitudes<float> fresnel_amplitudes(float cos_i, std::complex<float> eta) {
  return amplitudes<float>(cos_i, eta, false);
}
FresnelAmplitudes<double> fresnel_amplitudes(double cos_i, std::complex<double> eta) {
  return amplitudes<double>(cos_i, eta, false);
}
FresnelAmplitudes<float> fresnel_amplitudes_dielectric(float cos_i, float eta) {
  return dielectric_amplitudes<float>(cos_i, eta);
}
FresnelAmplitudes<double> fresnel_amplitudes_dielectric(double cos_i, double eta) {
  return dielectric_amplitudes<double>(cos_i, eta);
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
