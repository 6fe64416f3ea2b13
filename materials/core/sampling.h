#pragma once
// Direction sampling routines shared by lobes and lights.

#include "materials/core/vec3.h"

namespace ochre {

// Concentric mapping of [0,1)^2 to the unit disk (Shirley & Chiu 1997).
Vec2 sample_uniform_disk_concentric(const Vec2& u);
// Cosine-weighted hemisphere around +z; pdf = cos(theta) / pi.
Vec3 sample_cosine_hemisphere(const Vec2& u);
inline float cosine_hemisphere_pdf(float cos_theta) {
  return cos_theta > 0.0f ? cos_theta * kInvPi : 0.0f;
}
// Uniform direction on the unit sphere; pdf = 1 / (4 pi).
Vec3 sample_uniform_sphere(const Vec2& u);
inline constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPi);
// Uniform point on a triangle, returned as barycentrics (b0, b1) (Heitz 2019 low-distortion map).
Vec2 sample_uniform_triangle(const Vec2& u);
// Power heuristic (beta = 2) for multiple importance sampling.
inline float power_heuristic(float pdf_a, float pdf_b) {
  const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace ochre
