#include "materials/lobes/vgroove/vgroove_lobe.h"

#include <cmath>

#include "materials/lobes/fresnel.h"

namespace ochre {

VGrooveLobe::VGrooveLobe(double alpha, const Vec3& axis, const FacetSpectrum& facet, ChainModel model,
                         int reflection_limit)
    : groove_(alpha), frame_(axis), facet_(facet), model_(model), reflection_limit_(reflection_limit) {}

uint32_t VGrooveLobe::flags() const {
  return kLobeReflection | kLobeDelta | (groove_model_polarizes(model_) ? kLobePolarizing : 0u);
}

std::optional<LobeSample> VGrooveLobe::sample(const Vec3& wo, float, const Vec2& u,
                                              const SampledWavelengths&) const {
  if (!(wo.z > 0.0f)) return std::nullopt;
  const Vec3d e = normalize(frame_.to_groove(wo));
  const VGroovePath path = groove_.trace(e, (2.0 * u.x - 1.0) * groove_.half_opening());
  if (reflection_limit_ > 0 && path.reflections > reflection_limit_) return std::nullopt;  // absorbed
  GrooveResponses responses = groove_responses(model_, facet_);
  const ChainFrames chain = light_chain(groove_, path, [&](const ChainStep& step) {
    for (ChainResponse& r : responses) r.add(step);
  });
  return groove_sample(frame_, path.exit, chain, responses, groove_model_polarizes(model_));
}

MuellerResponse VGrooveLobe::eval_mueller(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return depolarizing_response(SampledSpectrum(0.0f), wo, wi);
}

SampledSpectrum facet_albedo_hint(const FacetSpectrum& facet, const Vec3& wo) {
  if (facet.mirror) return SampledSpectrum(1.0f);
  return fresnel_conductor(std::fabs(wo.z), facet.n, facet.k);
}

SampledSpectrum VGrooveLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  return facet_albedo_hint(facet_, wo);
}

}  // namespace ochre
