#pragma once
// Lambert: the ideal diffuse reflector f = 1/pi (its albedo is the closure weight, as in OSL's
// diffuse()). An ideal depolarizer. Cosine-weighted hemisphere sampling.

#include "materials/lobes/lobe.h"

namespace ochre {

class LambertLobe final : public Lobe {
 public:
  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  SampledSpectrum albedo_hint(const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(1.0f);
  }
};

}  // namespace ochre
