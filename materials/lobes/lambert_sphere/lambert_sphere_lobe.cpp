#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"

#include "materials/lobes/cosine_lobe_sampling.h"
#include "spectra/non_finite.h"

namespace ochre {

LambertSphereLobe::LambertSphereLobe(LambertSphereVariant variant, const SampledSpectrum& particle_albedo)
    : variant_(variant) {
  SampledSpectrum c;
  for (int k = 0; k < kSpectrumSamples; ++k) c[k] = nan_safe_clamp(particle_albedo[k], 0.0f, 1.0f);
  if (variant == LambertSphereVariant::kExact) {
    for (int k = 0; k < kSpectrumSamples; ++k) exact_[k] = lambert_sphere_exact_constants(c[k]);
  } else {
    fitted_ = lambert_sphere_constant_lanes(c.lanes(), variant == LambertSphereVariant::kFast);
  }
  for (int k = 0; k < kSpectrumSamples; ++k) albedo_[k] = lambert_sphere_kd_from_c_eq47(c[k]);
}

SampledSpectrum LambertSphereLobe::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  const float mu_i = wi.z, mu_o = wo.z;
  if (!(mu_i > 0.0f) || !(mu_o > 0.0f)) return SampledSpectrum(0.0f);
  const float wi_dot_wo = std::clamp(dot(wi, wo), -1.0f, 1.0f);
  SampledSpectrum f;
  if (variant_ == LambertSphereVariant::kExact) {
    const LambertSphereExactGeometry g = lambert_sphere_exact_geometry(mu_i, mu_o, wi_dot_wo);
    for (int k = 0; k < kSpectrumSamples; ++k) f[k] = lambert_sphere_exact(exact_[k], g);
    return f;
  }
  // The direction-dependent parts once for all the wavelengths (the fast variant reads no exponentials).
  if (variant_ == LambertSphereVariant::kFast) {
    const LambertSphereGeometry<float> g = lambert_sphere_phase_geometry(mu_i, mu_o, wi_dot_wo);
    const float factor = lambert_sphere_fast_factor(mu_i, mu_o, wi_dot_wo);
    for (int k = 0; k < kSpectrumSamples; ++k) f[k] = lambert_sphere_fast(fitted_.at(k), g, factor);
    return f;
  }
  const LambertSphereGeometry<float> g = lambert_sphere_geometry(mu_i, mu_o, wi_dot_wo);
  lambert_sphere_full_lanes(fitted_, g, f.lanes());
  return f;
}

float LambertSphereLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return cosine_lobe_pdf(wo, wi);
}

std::optional<LobeSample> LambertSphereLobe::sample(const Vec3& wo, float, const Vec2& u,
                                                    const SampledWavelengths& lambda) const {
  std::optional<LobeSample> s = sample_cosine_lobe(wo, u);
  if (s) {
    s->value = eval(wo, s->wi, lambda);
    s->has_value = true;
    s->weight = s->value * (s->wi.z / s->pdf);
  }
  return s;
}

SampledSpectrum LambertSphereLobe::albedo_hint(const Vec3&, const SampledWavelengths&) const {
  return albedo_;
}

}  // namespace ochre
