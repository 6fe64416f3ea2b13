#pragma once
// Point light: isotropic radiant intensity I(lambda) (W sr^-1 nm^-1) at a position.

#include "renderer/light.h"
#include "spectra/spectrum.h"

namespace ochre {

class PointLight final : public Light {
 public:
  PointLight(const Vec3& position, SpectrumPtr intensity);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override;
  bool is_delta() const override { return true; }

 private:
  Vec3 position_;
  SpectrumPtr intensity_;
};

}  // namespace ochre
