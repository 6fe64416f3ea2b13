#include "renderer/lights/spot_light.h"

#include <algorithm>
#include <cmath>

#include "renderer/lights/point_light.h"
#include "spectra/cie.h"

namespace ochre {

SpotLight::SpotLight(const Vec3& position, const Vec3& direction, float cone_angle_deg,
                     float falloff_start_deg, SpectrumPtr intensity, Falloff falloff)
    : position_(position),
      direction_(normalize(direction)),
      cos_cone_(std::cos(cone_angle_deg * kPi / 180.0f)),
      cos_falloff_(std::cos(falloff_start_deg * kPi / 180.0f)),
      cone_(cone_angle_deg * kPi / 180.0f),
      falloff_start_(falloff_start_deg * kPi / 180.0f),
      falloff_(falloff),
      intensity_(std::move(intensity)),
      luminance_(spectrum_to_xyz(*intensity_.spectrum()).y) {}

float SpotLight::profile(const Vec3& direction) const {
  const float c = dot(direction_, direction);
  if (c >= cos_falloff_) return 1.0f;
  if (c <= cos_cone_) return 0.0f;
  if (falloff_ == Falloff::Linear) return (cone_ - std::acos(c)) / (cone_ - falloff_start_);
  const float t = (c - cos_cone_) / (cos_falloff_ - cos_cone_);
  return t * t * (3.0f - 2.0f * t);  // smoothstep
}

std::optional<LightSample> SpotLight::sample(const Vec3& ref, const Vec2&,
                                             const SampledWavelengths& lambda) const {
  auto s = sample_point_source(position_, ref);
  if (!s) return std::nullopt;
  const float k = profile(-s->wi);
  if (k <= 0.0f) return std::nullopt;
  s->radiance *= intensity_.sample(lambda) * k;
  return s;
}

float SpotLight::power() const {
  // Integral of the profile over the sphere: the full cone plus the ring. The smoothstep's mean over the
  // ring (in cos) is 1/2; the linear ramp integrates to ((g - b) cos b + sin b - sin g) / (g - b) in
  // 2 pi sin(theta) d(theta) from b = falloff_start to g = cone.
  const float ring =
      falloff_ == Falloff::Smoothstep || cone_ == falloff_start_
          ? 0.5f * (cos_falloff_ - cos_cone_)
          : ((cone_ - falloff_start_) * cos_falloff_ + std::sin(falloff_start_) - std::sin(cone_)) /
                (cone_ - falloff_start_);
  const float solid_angle = 2.0f * kPi * ((1.0f - cos_falloff_) + ring);
  return solid_angle * luminance_;
}

float SpotLight::importance(const Vec3& p) const {
  const Vec3 d = p - position_;
  const float d2 = length_squared(d);
  if (!(d2 > 0.0f)) return 0.0f;
  return luminance_ * profile(d / std::sqrt(d2)) / d2;
}

}  // namespace ochre
