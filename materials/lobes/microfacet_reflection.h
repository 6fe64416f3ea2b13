#pragma once
// GGX microfacet reflection geometry shared by the rough specular lobes (conductor, dielectric):
// the lobe value is F(wo.h) D(h) G2(wo, wi) / (4 cos_o cos_i) (Walter et al. 2007 Eq. 20 with the
// height-correlated G2 of Heitz 2014), sampled through visible normals (Heitz 2018) with the pdf
// D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 cos_o) (Walter et al. 2007 Eq. 14). Both directions must lie
// above the surface (wo.z > 0, wi.z > 0); the lobes only add their Fresnel term.

#include <optional>

#include "materials/core/vec3.h"
#include "materials/lobes/microfacet_ggx.h"

namespace ochre {

struct MicrofacetReflectionSample {
  Vec3 wi;
  Vec3 h;                      // the microfacet normal that reflects wo into wi
  float pdf = 0.0f;            // solid angle, of wi
  float weight_factor = 0.0f;  // D G2 / (4 cos_o cos_i) * cos_i / pdf = G2 / G1(wo); times F = weight
};

class MicrofacetReflection {
 public:
  explicit MicrofacetReflection(const GgxDistribution& ggx) : ggx_(ggx) {}

  const GgxDistribution& distribution() const { return ggx_; }
  // The half vector of a valid reflection configuration, else nothing.
  static std::optional<Vec3> half_vector(const Vec3& wo, const Vec3& wi);
  // D G2 / (4 cos_o cos_i) at half vector h (without Fresnel; 0 for invalid configurations).
  float geometric_term(const Vec3& wo, const Vec3& wi, const Vec3& h) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  std::optional<MicrofacetReflectionSample> sample(const Vec3& wo, const Vec2& u) const;

 private:
  GgxDistribution ggx_;
};

}  // namespace ochre
