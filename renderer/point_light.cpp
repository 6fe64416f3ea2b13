#include "renderer/point_light.h"

#include "spectra/cie.h"

namespace ochre {

PointLight::PointLight(const Vec3& position, SpectrumPtr intensity)
    : position_(position), intensity_(std::move(intensity)) {}

std::optional<LightSample> PointLight::sample(const Vec3& ref, const Vec2&,
                                              const SampledWavelengths& lambda) const {
  const Vec3 d = position_ - ref;
  const float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return std::nullopt;
  LightSample s;
  s.distance = std::sqrt(dist2);
  s.wi = d / s.distance;
  s.radiance = intensity_->sample(lambda) / dist2;  // inverse-square law
  s.pdf = 1.0f;
  s.delta = true;
  return s;
}

float PointLight::power() const {
  return 4.0f * kPi * spectrum_to_xyz(*intensity_).y;
}

}  // namespace ochre
