#include "materials/lobes/vgroove/microgroove_lobe.h"

#include <algorithm>
#include <array>

#include "materials/lobes/vgroove/vgroove_lobe.h"

namespace ochre {

MicrogrooveLobe::MicrogrooveLobe(const MicrogrooveShape& shape, const Vec3& axis, const FacetSpectrum& facet,
                                 ChainModel model, int reflection_limit)
    : shape_(shape), frame_(axis), facet_(facet), model_(model), reflection_limit_(reflection_limit) {}

uint32_t MicrogrooveLobe::flags() const {
  return kLobeReflection | kLobeDelta | (groove_model_polarizes(model_) ? kLobePolarizing : 0u);
}

std::optional<LobeSample> MicrogrooveLobe::sample_profile(const GrooveProfile& profile, const Vec3d& e,
                                                          double u) const {
  std::array<uint8_t, kMaxReflections> facets;  // indices of the facets met, traced order
  Vec3d exit;
  const int count = profile.trace(e, u, facets, exit);
  if (count < 1 || (reflection_limit_ > 0 && count > reflection_limit_)) return std::nullopt;  // absorbed
  GrooveResponses responses = groove_responses(model_, facet_);
  const ChainFrames chain = reversed_light_chain(
      exit, count, [&](int j) -> const Vec3d& { return profile.segment(facets[j - 1]).normal; },
      [&](const ChainStep& step) {
        for (ChainResponse& r : responses) r.add(step);
      });
  return groove_sample(frame_, exit, chain, responses, groove_model_polarizes(model_));
}

std::optional<LobeSample> MicrogrooveLobe::sample(const Vec3& wo, float u_choice, const Vec2& u,
                                                  const SampledWavelengths&) const {
  if (!(wo.z > 0.0f)) return std::nullopt;
  const Vec3d e = normalize(frame_.to_groove(wo));
  if (shape_.profile) return sample_profile(*shape_.profile, e, u.x);
  const double alpha = shape_.alpha_min + double(u_choice) * (shape_.alpha_max - shape_.alpha_min);
  return sample_profile(GrooveProfile::v(alpha), e, u.x);
}

MuellerResponse MicrogrooveLobe::eval_mueller(const Vec3& wo, const Vec3& wi,
                                              const SampledWavelengths&) const {
  return depolarizing_response(SampledSpectrum(0.0f), wo, wi);
}

SampledSpectrum MicrogrooveLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  return facet_albedo_hint(facet_, wo);
}

}  // namespace ochre
