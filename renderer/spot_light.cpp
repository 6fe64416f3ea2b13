#include "renderer/spot_light.h"

#include <algorithm>
#include <cmath>

#include "renderer/point_light.h"
#include "spectra/cie.h"

namespace ochre {

SpotLight::SpotLight(const Vec3& position, const Vec3& direction, float cone_angle_deg,
                     float falloff_start_deg, SpectrumPtr intensity)
    : position_(position),
      direction_(normalize(direction)),
      cos_cone_(std::cos(cone_angle_deg * kPi / 180.0f)),
      cos_falloff_(std::cos(falloff_start_deg * kPi / 180.0f)),
      intensity_(std::move(intensity)) {}

float SpotLight::profile(const Vec3& direction) const {
  const float c = dot(direction_, direction);
  if (c >= cos_falloff_) return 1.0f;
  if (c <= cos_cone_) return 0.0f;
  const float t = (c - cos_cone_) / (cos_falloff_ - cos_cone_);
  return t * t * (3.0f - 2.0f * t);  // smoothstep
}

std::optional<LightSample> SpotLight::sample(const Vec3& ref, const Vec2&,
                                             const SampledWavelengths& lambda) const {
  auto s = sample_point_source(position_, ref);
  if (!s) return std::nullopt;
  const float k = profile(-s->wi);
  if (k <= 0.0f) return std::nullopt;
  s->radiance *= intensity_->sample(lambda) * k;
  return s;
}

float SpotLight::power() const {
  // Integral of the profile over the sphere: full cone plus the smoothstep ring (its mean is 1/2).
  const float solid_angle = 2.0f * kPi * ((1.0f - cos_falloff_) + 0.5f * (cos_falloff_ - cos_cone_));
  return solid_angle * spectrum_to_xyz(*intensity_).y;
}

}  // namespace ochre
