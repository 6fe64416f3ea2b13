#pragma once
// Point light: isotropic radiant intensity I(lambda) (W sr^-1 nm^-1) at a position.

#include "renderer/lights/light.h"
#include "spectra/memoized_spectrum.h"

namespace ochre {

// Direction, distance and inverse-square falloff from `ref` to a point source at `position`
// (radiance = 1 / distance^2, to be multiplied by the source's intensity). Shared by point and spot lights.
std::optional<LightSample> sample_point_source(const Vec3& position, const Vec3& ref);

class PointLight final : public Light {
 public:
  PointLight(const Vec3& position, SpectrumPtr intensity);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override;
  float importance(const Vec3& p) const override;
  bool is_delta() const override { return true; }
  const Spectrum* emission_spectrum() const override { return intensity_.spectrum().get(); }

 private:
  Vec3 position_;
  MemoizedSpectrum intensity_;
  float luminance_;  // of the intensity
};

}  // namespace ochre
