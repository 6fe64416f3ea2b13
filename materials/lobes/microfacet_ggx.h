#pragma once
// The GGX (Trowbridge-Reitz) microfacet distribution, anisotropic with roughnesses alpha_x, alpha_y
// along the local x and y axes (isotropic when equal), in the local shading frame (z = normal).
// - D(m): Walter et al. 2007 Eq. 33, written as 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2)
//   (Heitz 2014 "Understanding the masking-shadowing function", Eq. 85), which stays finite for
//   alpha down to 1e-4 and for grazing m.
// - Lambda(w) = (-1 + sqrt(1 + (ax^2 wx^2 + ay^2 wy^2) / wz^2)) / 2 (Heitz 2014 Eq. 86);
//   G1 = 1 / (1 + Lambda); G2 height-correlated = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014 Eq. 99).
// - Visible-normal sampling: Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)),
//   Listing 1; the density of visible normals is D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z (Eq. 1).

#include "materials/core/vec3.h"

namespace ochre {

class GgxDistribution {
 public:
  // Roughnesses below kMinAlpha are raised to it (a numerically safe, visually smooth lobe); NaN counts as
  // kMinAlpha. Above kMaxAlpha alpha^2 would overflow in the sampling: such roughnesses are lowered to it.
  static constexpr float kMinAlpha = 1e-4f;
  static constexpr float kMaxAlpha = 1e15f;

  GgxDistribution(float alpha_x, float alpha_y);
  explicit GgxDistribution(float alpha) : GgxDistribution(alpha, alpha) {}

  float alpha_x() const { return ax_; }
  float alpha_y() const { return ay_; }

  // Normal distribution D(m) for a unit microfacet normal m (0 for m.z <= 0).
  float d(const Vec3& m) const;
  float lambda(const Vec3& w) const;
  float g1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated masking-shadowing of a reflection (wo, wi on the same side).
  float g2(const Vec3& wo, const Vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

  // Draws a microfacet normal visible from wo (wo.z > 0) with density visible_normal_pdf(wo, m).
  Vec3 sample_visible_normal(const Vec3& wo, float u1, float u2) const;
  float visible_normal_pdf(const Vec3& wo, const Vec3& m) const;

 private:
  float ax_, ay_;
};

// Reflection of w about the unit normal m.
inline Vec3 reflect(const Vec3& w, const Vec3& m) {
  return m * (2.0f * dot(w, m)) - w;
}

}  // namespace ochre
