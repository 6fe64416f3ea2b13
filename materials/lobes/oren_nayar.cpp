#include "materials/lobes/oren_nayar.h"

#include <algorithm>
#include <cmath>

#include "materials/lobes/cosine_lobe_sampling.h"
#include "spectra/non_finite.h"

namespace ochre {

OrenNayarLobe::OrenNayarLobe(float sigma_radians) {
  // Beyond 1e18 A and B have reached their limits 1/2 and 0.45 in float; s^2 must stay finite (inf / inf
  // is NaN), and NaN counts as 0.
  const float sigma = nan_safe_clamp(std::fabs(sigma_radians), 0.0f, 1e18f);
  const float s2 = sigma * sigma;
  a_ = 1.0f - 0.5f * s2 / (s2 + 0.33f);
  b_ = 0.45f * s2 / (s2 + 0.09f);
}

float OrenNayarLobe::value(const Vec3& wo, const Vec3& wi) const {
  if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
  // sin(alpha) tan(beta) = sin_i sin_o / cos(beta) (alpha the larger angle, beta the smaller: the
  // larger cosine), and cos(phi_i - phi_o) sin_i sin_o = wi.x wo.x + wi.y wo.y: no division at the pole.
  const float tangential = std::max(0.0f, wi.x * wo.x + wi.y * wo.y);
  const float term = tangential / std::max(wi.z, wo.z);
  return kInvPi * (a_ + b_ * term);
}

SampledSpectrum OrenNayarLobe::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return SampledSpectrum(value(wo, wi));
}

float OrenNayarLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return cosine_lobe_pdf(wo, wi);
}

std::optional<LobeSample> OrenNayarLobe::sample(const Vec3& wo, float, const Vec2& u,
                                                const SampledWavelengths&) const {
  std::optional<LobeSample> s = sample_cosine_lobe(wo, u);
  if (s) s->weight = SampledSpectrum(value(wo, s->wi) * (s->wi.z / s->pdf));
  return s;
}

}  // namespace ochre
