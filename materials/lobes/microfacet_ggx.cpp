#include "materials/lobes/microfacet_ggx.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spectra/non_finite.h"

namespace ochre {

GgxDistribution::GgxDistribution(float alpha_x, float alpha_y)
    : ax_(nan_safe_clamp(alpha_x, kMinAlpha, kMaxAlpha)),
      ay_(nan_safe_clamp(alpha_y, kMinAlpha, kMaxAlpha)) {}

float GgxDistribution::d(const Vec3& m) const {
  if (m.z <= 0.0f) return 0.0f;
  const float x = m.x / ax_, y = m.y / ay_;
  const float s = x * x + y * y + m.z * m.z;
  return 1.0f / (kPi * ax_ * ay_ * s * s);
}

float GgxDistribution::lambda(const Vec3& w) const {
  const float z2 = w.z * w.z;
  if (z2 == 0.0f) return std::numeric_limits<float>::infinity();  // grazing: fully masked
  const float a2_tan2 = (ax_ * ax_ * w.x * w.x + ay_ * ay_ * w.y * w.y) / z2;
  return 0.5f * (std::sqrt(1.0f + a2_tan2) - 1.0f);
}

Vec3 GgxDistribution::sample_visible_normal(const Vec3& wo, float u1, float u2) const {
  // Heitz 2018, Listing 1. Section 1: the view direction in the hemisphere configuration.
  const Vec3 vh = normalize(Vec3(ax_ * wo.x, ay_ * wo.y, wo.z));
  // Section 2: orthonormal basis (with the special case where vh is the normal).
  const float len2 = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = len2 > 0.0f ? Vec3(-vh.y, vh.x, 0.0f) / std::sqrt(len2) : Vec3(1, 0, 0);
  const Vec3 t2 = cross(vh, t1);
  // Section 3: a point on the projected area of the hemisphere.
  const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + vh.z);
  const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
  // Section 4: reprojection onto the hemisphere.
  const Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2));
  // Section 3.4: back to the ellipsoid configuration.
  return normalize(Vec3(ax_ * nh.x, ay_ * nh.y, std::max(0.0f, nh.z)));
}

float GgxDistribution::visible_normal_pdf(const Vec3& wo, const Vec3& m) const {
  if (wo.z <= 0.0f) return 0.0f;
  const float wo_m = dot(wo, m);
  if (wo_m <= 0.0f) return 0.0f;
  return g1(wo) * wo_m * d(m) / wo.z;
}

}  // namespace ochre
