#pragma once
// Oren-Nayar rough diffuse reflection, the "qualitative" model of Oren & Nayar 1994 (their Eq 30,
// the simplification without the C3 term and without interreflections that pbrt and most
// renderers use), with unit albedo (the closure weight is the albedo, as for Lambert):
//   f = 1/pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
//   A = 1 - 0.5 s^2 / (s^2 + 0.33), B = 0.45 s^2 / (s^2 + 0.09),
// alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o), s = sigma, the standard deviation of
// the facet slope angle in radians. sigma = 0 is Lambert. Not energy conserving for large sigma
// in the sense of the full model (the qualitative form drops the interreflection term; its
// directional albedo stays <= 1). An ideal depolarizer; cosine-weighted sampling.

#include "materials/lobes/lobe.h"

namespace ochre {

class OrenNayarLobe final : public Lobe {
 public:
  explicit OrenNayarLobe(float sigma_radians);

  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  SampledSpectrum albedo_hint(const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(1.0f);
  }

  // The BRDF value (unit albedo) for unit wo, wi in the local frame.
  float value(const Vec3& wo, const Vec3& wi) const;

 private:
  float a_, b_;
};

}  // namespace ochre
