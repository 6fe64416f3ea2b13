#pragma once
// Constant environment: radiance L(lambda) arriving from every direction at infinity.
// Sampled uniformly over the sphere (HDR maps with importance sampling come in Backbone II).

#include "renderer/light.h"
#include "spectra/spectrum.h"

namespace ochre {

class EnvironmentLight final : public Light {
 public:
  EnvironmentLight(SpectrumPtr radiance, float scene_radius);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override;

  // Radiance arriving along -direction (a ray escaping the scene along `direction`).
  SampledSpectrum radiance(const Vec3& direction, const SampledWavelengths& lambda) const;
  // Solid-angle pdf of sample() producing `direction`.
  float pdf(const Vec3& direction) const;

 private:
  SpectrumPtr radiance_;
  float scene_radius_;
};

}  // namespace ochre
