#include "renderer/lights/sphere_light.h"

#include <algorithm>
#include <cmath>

#include "materials/core/frame.h"
#include "renderer/lights/point_light.h"
#include "spectra/cie.h"

namespace ochre {

SphereLight::SphereLight(const Vec3& center, float radius, SpectrumPtr intensity)
    : center_(center),
      radius_(radius),
      intensity_(std::move(intensity)),
      luminance_(spectrum_to_xyz(*intensity_.spectrum()).y) {}

void SphereLight::set_state(const Vec3& center, SpectrumPtr intensity) {
  center_ = center;
  intensity_ = MemoizedSpectrum(std::move(intensity));
  luminance_ = spectrum_to_xyz(*intensity_.spectrum()).y;
}

std::optional<LightSample> SphereLight::sample(const Vec3& ref, const Vec2& u,
                                               const SampledWavelengths& lambda) const {
  const Vec3 to_center = center_ - ref;
  const float dist2 = dot(to_center, to_center);
  const float r2 = radius_ * radius_;
  if (!(dist2 > r2 * 1.0001f)) {
    // Inside (or on) the sphere: a point light at the centre no closer than the radius.
    auto s = sample_point_source(center_, ref);
    if (!s) return std::nullopt;
    s->radiance = intensity_.sample(lambda) * (1.0f / std::max(dist2, r2));
    return s;
  }
  const float dist = std::sqrt(dist2);
  const float sin2_max = r2 / dist2;
  const float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2_max));
  // Uniform in the cone; 1 - cos is computed from sin^2 for small cones, where 1 - cos_max cancels.
  const float one_minus_cos_max = sin2_max < 1e-3f ? 0.5f * sin2_max : 1.0f - cos_max;
  const float one_minus_cos = u.x * one_minus_cos_max;
  const float cos_theta = 1.0f - one_minus_cos;
  const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
  const float phi = 2.0f * kPi * u.y;
  const Frame frame = Frame::from_normal(to_center / dist);
  LightSample s;
  s.wi = normalize(frame.to_world({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta}));
  // Distance to the near side of the sphere along wi.
  const float b = dist * cos_theta;
  s.distance = std::max(0.0f, b - std::sqrt(std::max(0.0f, r2 - dist2 + b * b)));
  s.pdf = 1.0f / (2.0f * kPi * one_minus_cos_max);
  s.radiance = intensity_.sample(lambda) * (1.0f / (kPi * r2));
  s.only_by_light_sampling = true;
  return s;
}

float SphereLight::power() const {
  return 4.0f * kPi * luminance_;
}

float SphereLight::importance(const Vec3& p) const {
  // A point light at the centre, never nearer than r (see the header).
  return luminance_ / std::max(length_squared(center_ - p), radius_ * radius_);
}

}  // namespace ochre
