#include "materials/lambert.h"

#include "materials/sampling.h"

namespace ochre {

SampledSpectrum LambertLobe::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return SampledSpectrum(0.0f);
  return SampledSpectrum(kInvPi);
}

float LambertLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  if (wo.z <= 0.0f) return 0.0f;
  return cosine_hemisphere_pdf(wi.z);
}

std::optional<LobeSample> LambertLobe::sample(const Vec3& wo, float, const Vec2& u,
                                              const SampledWavelengths&) const {
  if (wo.z <= 0.0f) return std::nullopt;
  LobeSample s;
  s.wi = sample_cosine_hemisphere(u);
  s.pdf = cosine_hemisphere_pdf(s.wi.z);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = SampledSpectrum(1.0f);  // (1/pi) cos / (cos/pi)
  return s;
}

}  // namespace ochre
