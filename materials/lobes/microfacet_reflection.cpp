#include "materials/lobes/microfacet_reflection.h"

#include <cmath>

namespace ochre {

std::optional<Vec3> MicrofacetReflection::half_vector(const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
  const Vec3 sum = wo + wi;
  const float len2 = dot(sum, sum);
  if (!(len2 > 0.0f)) return std::nullopt;
  return sum / std::sqrt(len2);
}

float MicrofacetReflection::geometric_term(const Vec3& wo, const Vec3& wi, const Vec3& h) const {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  return ggx_.d(h) * ggx_.g2(wo, wi) / (4.0f * wo.z * wi.z);
}

float MicrofacetReflection::pdf(const Vec3& wo, const Vec3& wi) const {
  const std::optional<Vec3> h = half_vector(wo, wi);
  if (!h) return 0.0f;
  const float wo_h = dot(wo, *h);
  if (wo_h <= 0.0f) return 0.0f;
  return ggx_.visible_normal_pdf(wo, *h) / (4.0f * wo_h);
}

std::optional<MicrofacetReflectionSample> MicrofacetReflection::sample(const Vec3& wo, const Vec2& u) const {
  if (wo.z <= 0.0f) return std::nullopt;
  MicrofacetReflectionSample s;
  s.h = ggx_.sample_visible_normal(wo, u.x, u.y);
  const float wo_h = dot(wo, s.h);
  if (!(wo_h > 0.0f)) return std::nullopt;
  s.wi = reflect(wo, s.h);
  if (s.wi.z <= 0.0f) return std::nullopt;  // reflected below the surface: the sample is lost
  // The half vector recomputed from (wo, wi), as eval() and pdf() see it: at tiny roughness D is so
  // peaked that the rounding of reflect() alone would make the weight disagree with eval |cos| / pdf.
  const std::optional<Vec3> h = half_vector(wo, s.wi);
  if (!h) return std::nullopt;
  s.h = *h;
  s.pdf = pdf(wo, s.wi);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight_factor = geometric_term(wo, s.wi, s.h) * s.wi.z / s.pdf;
  return s;
}

}  // namespace ochre
