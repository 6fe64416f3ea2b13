#include "materials/core/sampling.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

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

// c ? a : b by bit masks: compilers turn a float ?: into a branch, which a coin-toss condition mispredicts
// half the time.
float select(bool c, float a, float b) {
  const uint32_t mask = 0u - static_cast<uint32_t>(c);
  return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) | (std::bit_cast<uint32_t>(b) & ~mask));
}

}  // namespace

Vec2 sample_uniform_disk_concentric(const Vec2& u) {
  const float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
  if (ox == 0.0f && oy == 0.0f) return {0.0f, 0.0f};
  // |ox| > |oy|: r = ox, theta = pi/4 (oy / ox) in [-pi/4, pi/4]. Otherwise r = oy, theta = pi/2 - phi with
  // phi = pi/4 (ox / oy): cos theta = sin phi, sin theta = cos phi. Selects, not branches.
  const bool wide = std::fabs(ox) > std::fabs(oy);
  const float r = select(wide, ox, oy);
  const Vec2 cs = cos_sin_quarter_pi((kPi / 4.0f) * (select(wide, oy, ox) / r));
  return {r * select(wide, cs.x, cs.y), r * select(wide, cs.y, cs.x)};
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
  // Heitz's map: half the smaller coordinate is taken from both (x - x/2 = x/2 exactly, so this is the
  // paper's two cases without a branch, which u would make a coin toss).
  const float half = std::min(u.x, u.y) / 2.0f;
  return {u.x - half, u.y - half};
}

}  // namespace ochre
