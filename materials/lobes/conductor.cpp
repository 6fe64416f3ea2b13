#include "materials/lobes/conductor.h"

#include <complex>

#include "materials/core/specular_frame.h"
#include "materials/lobes/fresnel.h"

namespace ochre {

MuellerSpectrum conductor_reflection_mueller(float cos_i, const SampledSpectrum& n,
                                             const SampledSpectrum& k) {
  MuellerSpectrum m;
  for (int i = 0; i < kSpectrumSamples; ++i)
    m[i] = specular_reflection(cos_i, std::complex<float>(n[i], -k[i]));
  return m;
}

namespace {

Vec3 mirror(const Vec3& wo) {
  return {-wo.x, -wo.y, wo.z};
}

}  // namespace

std::optional<LobeSample> SmoothConductorLobe::sample(const Vec3& wo, float, const Vec2&,
                                                      const SampledWavelengths&) const {
  if (wo.z <= 0.0f) return std::nullopt;
  LobeSample s;
  s.wi = mirror(wo);
  s.pdf = 1.0f;  // the only exit
  s.delta = true;
  s.has_mueller = true;
  s.mueller.m = conductor_reflection_mueller(wo.z, n_, k_);
  s.mueller.in_x = s.mueller.out_x = s_polarization_axis(s.wi, Vec3(0, 0, 1));
  s.weight = m00(s.mueller.m);
  return s;
}

MuellerResponse SmoothConductorLobe::eval_mueller(const Vec3& wo, const Vec3& wi,
                                                  const SampledWavelengths&) const {
  return zero_response(wo, wi);
}

SampledSpectrum SmoothConductorLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  return fresnel_conductor(std::fabs(wo.z), n_, k_);
}

SampledSpectrum RoughConductorLobe::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  const std::optional<Vec3> h = MicrofacetReflection::half_vector(wo, wi);
  if (!h) return SampledSpectrum(0.0f);
  const float g = microfacets_.geometric_term(wo, wi, *h);
  if (!(g > 0.0f)) return SampledSpectrum(0.0f);
  return fresnel_conductor(dot(wo, *h), n_, k_) * g;
}

float RoughConductorLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return microfacets_.pdf(wo, wi);
}

std::optional<LobeSample> RoughConductorLobe::sample(const Vec3& wo, float, const Vec2& u,
                                                     const SampledWavelengths&) const {
  const std::optional<MicrofacetReflectionSample> m = microfacets_.sample(wo, u);
  if (!m) return std::nullopt;
  LobeSample s;
  s.wi = m->wi;
  s.pdf = m->pdf;
  s.has_mueller = true;
  s.mueller.m = conductor_reflection_mueller(dot(wo, m->h), n_, k_) * m->weight_factor;
  s.mueller.in_x = s.mueller.out_x = s_polarization_axis(s.wi, m->h);
  s.weight = m00(s.mueller.m);
  return s;
}

MuellerResponse RoughConductorLobe::eval_mueller(const Vec3& wo, const Vec3& wi,
                                                 const SampledWavelengths&) const {
  const std::optional<Vec3> h = MicrofacetReflection::half_vector(wo, wi);
  if (!h) return zero_response(wo, wi);
  MuellerResponse r;
  r.m = conductor_reflection_mueller(dot(wo, *h), n_, k_) * microfacets_.geometric_term(wo, wi, *h);
  r.in_x = r.out_x = s_polarization_axis(wi, *h);
  return r;
}

SampledSpectrum RoughConductorLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  return fresnel_conductor(std::fabs(wo.z), n_, k_);
}

}  // namespace ochre
