#pragma once
// Cosine-weighted hemisphere sampling as a reflection lobe's sampler (Lambert, Oren-Nayar, Lambert
// sphere, Chandrasekhar): nothing is sampled or has density when the viewer is below the surface. The
// caller sets the sample's weight from its own eval().

#include <optional>

#include "materials/core/sampling.h"
#include "materials/lobes/lobe.h"

namespace ochre {

inline float cosine_lobe_pdf(const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0f) return 0.0f;
  return cosine_hemisphere_pdf(wi.z);
}

// A direction and its pdf; `weight` is left for the lobe (f cos / pdf). Built in the returned optional (one
// named return value, so no copy: a LobeSample carries a Mueller response of 0.5 KB).
inline std::optional<LobeSample> sample_cosine_lobe(const Vec3& wo, const Vec2& u) {
  std::optional<LobeSample> out;
  if (wo.z <= 0.0f) return out;
  LobeSample& s = out.emplace();
  s.wi = sample_cosine_hemisphere(u);
  s.pdf = cosine_hemisphere_pdf(s.wi.z);
  if (!(s.pdf > 0.0f)) out.reset();
  return out;
}

}  // namespace ochre
