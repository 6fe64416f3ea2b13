#include "materials/core/sampling.h"

#include <cmath>

namespace ochre {

namespace {

// cos and sin of |x| <= pi/4 by their Taylor series to x^10 and x^9: the first omitted terms are below
// 1.2e-10 and 1.8e-9, far under float rounding, at a fraction of the cost of a general sincosf.
Vec2 cos_sin_quarter_pi(float x) {
  const float x2 = x * x;
  const float c =
      1.0f + x2 * (-1.0f / 2 + x2 * (1.0f / 24 + x2 * (-1.0f / 720 + x2 * (1.0f / 40320 - x2 / 3628800))));
  const float s =
      x * (1.0f + x2 * (-1.0f / 6 + x2 * (1.0f / 120 + x2 * (-1.0f / 5040 + x2 * (1.0f / 362880)))));
  return {c, s};
}

}  // namespace

Vec2 sample_uniform_disk_concentric(const Vec2& u) {
  const float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
  if (ox == 0.0f && oy == 0.0f) return {0.0f, 0.0f};
  if (std::fabs(ox) > std::fabs(oy)) {  // theta = pi/4 (oy / ox) in [-pi/4, pi/4]
    const Vec2 cs = cos_sin_quarter_pi((kPi / 4.0f) * (oy / ox));
    return {ox * cs.x, ox * cs.y};
  }
  // theta = pi/2 - phi with phi = pi/4 (ox / oy): cos theta = sin phi, sin theta = cos phi.
  const Vec2 cs = cos_sin_quarter_pi((kPi / 4.0f) * (ox / oy));
  return {oy * cs.y, oy * cs.x};
}

Vec3 sample_cosine_hemisphere(const Vec2& u) {
  const Vec2 d = sample_uniform_disk_concentric(u);
  const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

Vec3 sample_uniform_sphere(const Vec2& u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec2 sample_uniform_triangle(const Vec2& u) {
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2.0f;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2.0f;
    b0 = u.x - b1;
  }
  return {b0, b1};
}

}  // namespace ochre
