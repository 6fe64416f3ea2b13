#include "materials/lobes/lambert.h"

#include "materials/lobes/cosine_lobe_sampling.h"

namespace ochre {

SampledSpectrum LambertLobe::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return SampledSpectrum(0.0f);
  return SampledSpectrum(kInvPi);
}

float LambertLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return cosine_lobe_pdf(wo, wi);
}

std::optional<LobeSample> LambertLobe::sample(const Vec3& wo, float, const Vec2& u,
                                              const SampledWavelengths&) const {
  std::optional<LobeSample> s = sample_cosine_lobe(wo, u);
  if (s) s->weight = SampledSpectrum(1.0f);  // (1/pi) cos / (cos/pi)
  return s;
}

}  // namespace ochre
