#pragma once
// Fresnel equations: complex amplitude coefficients, scalar reflectances and the Mueller matrices of
// a specular reflection and refraction (docs/polarization.md, "Fresnel and Mueller matrices").
//
// Conventions (docs/polarization.md, 'Conventions'; they are Mitsuba 3's):
// - eta is the RELATIVE index n_transmitted / n_incident. cos_i >= 0 is the incidence cosine on the
//   incident side. The dielectric functions also accept cos_i < 0, meaning "incident from the other
//   side": they use |cos_i| and 1 / eta (pbrt's and Mitsuba's convention).
// - A complex index is eta = n - i k with k >= 0 (time dependence exp(+i w t)); tabulated n + i k data
//   (refractiveindex.info) is conjugated by passing (n, k) to the functions taking them separately.
// - cos_t = sqrt(1 - sin_i^2 / eta^2) on the branch with Im(cos_t) <= 0 (the transmitted wave decays;
//   for a real eta under total internal reflection this is cos_t = -i sqrt(sin_i^2 / eta^2 - 1), the
//   limit of a lossy medium as k -> 0+; it fixes the sign of the TIR phase).
// - Amplitudes in the Verdet (Born & Wolf) form: r_s = (cos_i - eta cos_t) / (cos_i + eta cos_t),
//   r_p = (eta cos_i - cos_t) / (eta cos_i + cos_t): at normal incidence on glass r_s = -0.2 and
//   r_p = +0.2. They relate field components in frames x = s (perpendicular to the plane of
//   incidence, the same vector for both beams) and y = cross(d, x) for each beam's direction d.
//   Transmission: t_s = 2 cos_i / (cos_i + eta cos_t) = 1 + r_s, t_p = 2 cos_i / (eta cos_i + cos_t).

#include <complex>

#include "materials/core/mueller.h"

namespace ochre {

template <class T>
struct FresnelAmplitudes {
  std::complex<T> r_s, r_p;  // reflection amplitudes
  std::complex<T> t_s, t_p;  // transmission amplitudes (0 under total internal reflection)
  std::complex<T> cos_t;     // transmitted cosine (branch above; purely imaginary under TIR)
  T eta;                     // |eta| actually used (after the side inversion of the dielectric)
  bool total_internal_reflection = false;
};

// Complex index n - i k, cos_i in [0, 1] (conductor or absorbing dielectric).
FresnelAmplitudes<float> fresnel_amplitudes(float cos_i, std::complex<float> eta);
FresnelAmplitudes<double> fresnel_amplitudes(double cos_i, std::complex<double> eta);
// Real relative index (> 0), either side (see above), with total internal reflection.
FresnelAmplitudes<float> fresnel_amplitudes_dielectric(float cos_i, float eta);
FresnelAmplitudes<double> fresnel_amplitudes_dielectric(double cos_i, double eta);

// Unpolarized reflectance (|r_s|^2 + |r_p|^2) / 2.
float fresnel_dielectric(float cos_i, float eta);
float fresnel_conductor(float cos_i, float n, float k);
SampledSpectrum fresnel_conductor(float cos_i, const SampledSpectrum& n, const SampledSpectrum& k);

// Mueller matrix of a reflection with amplitudes r_s, r_p, in frames x = s for both beams and
// y = cross(d, x) for each (the note's matrix): with R = |r|^2 and w = r_s conj(r_p) = c exp(-i Delta),
//   [[(Rs+Rp)/2, (Rs-Rp)/2, 0, 0], [(Rs-Rp)/2, (Rs+Rp)/2, 0, 0], [0, 0, Re w, Im w], [0, 0, -Im w, Re w]].
Mueller fresnel_reflection_mueller(std::complex<float> r_s, std::complex<float> r_p);
// Specular reflection off a dielectric (real eta, either side) and a conductor (eta = n - i k).
Mueller specular_reflection(float cos_i, float eta);
Mueller specular_reflection(float cos_i, std::complex<float> eta);
// Specular refraction through a dielectric interface, same frames (x = s for both beams): the
// transmittances T = eta Re(cos_t) / cos_i |t|^2 (power, so R + T = 1) on the diagonal blocks; zero
// under total internal reflection. Radiance compression (1 / eta^2) is the lobe's business, not this.
Mueller specular_transmission(float cos_i, float eta);

}  // namespace ochre
