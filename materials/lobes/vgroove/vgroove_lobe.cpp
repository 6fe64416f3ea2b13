#include "materials/lobes/vgroove/vgroove_lobe.h"

#include <array>
#include <cmath>

#include "materials/lobes/fresnel.h"

namespace ochre {

VGrooveLobe::VGrooveLobe(double alpha, const Vec3& axis, const FacetSpectrum& facet, ChainModel model,
                         int reflection_limit)
    : groove_(alpha), facet_(facet), model_(model), reflection_limit_(reflection_limit) {
  const double len = std::hypot(double(axis.x), double(axis.y));
  axis_ = len > 0.0 ? Vec3d(axis.x / len, axis.y / len, 0.0) : Vec3d(1.0, 0.0, 0.0);
  across_ = {-axis_.y, axis_.x, 0.0};
}

uint32_t VGrooveLobe::flags() const {
  const bool polarizing = model_ == ChainModel::kRigorous || model_ == ChainModel::kSeparateSP;
  return kLobeReflection | kLobeDelta | (polarizing ? kLobePolarizing : 0u);
}

Vec3d VGrooveLobe::to_groove(const Vec3& v) const {
  const Vec3d d(v);
  return {dot(d, axis_), dot(d, across_), d.z};
}

Vec3 VGrooveLobe::from_groove(const Vec3d& v) const {
  return (axis_ * v.x + across_ * v.y + Vec3d(0.0, 0.0, v.z)).to_float();
}

std::optional<LobeSample> VGrooveLobe::sample(const Vec3& wo, float, const Vec2& u,
                                               const SampledWavelengths&) const {
  if (!(wo.z > 0.0f)) return std::nullopt;
  const Vec3d e = normalize(to_groove(wo));
  const VGroovePath path = groove_.trace(e, (2.0 * u.x - 1.0) * groove_.half_opening());
  if (reflection_limit_ > 0 && path.reflections > reflection_limit_) return std::nullopt;  // absorbed

  std::array<ChainResponse, kSpectrumSamples> responses = {
      ChainResponse(model_, facet_.at(0)), ChainResponse(model_, facet_.at(1)), ChainResponse(model_, facet_.at(2)),
      ChainResponse(model_, facet_.at(3))};
  const ChainFrames frames = light_chain(groove_, path, [&](const ChainStep& step) {
    for (ChainResponse& r : responses) r.add(step);
  });

  LobeSample s;
  s.wi = from_groove(path.exit);
  if (!(s.wi.z > 0.0f)) s.wi.z = 1e-7f;  // a grazing exit rounded onto the horizon stays above it
  s.pdf = 1.0f;  // the uniform entry position makes the estimator unbiased; no MIS after a delta lobe
  s.delta = true;
  for (int i = 0; i < kSpectrumSamples; ++i) s.weight[i] = static_cast<float>(responses[i].reflectance());
  if (flags() & kLobePolarizing) {
    s.has_mueller = true;
    for (int i = 0; i < kSpectrumSamples; ++i) s.mueller.m[i] = responses[i].mueller();
    s.mueller.in_x = from_groove(frames.first_s());
    s.mueller.out_x = from_groove(frames.last_s());
  }
  return s;
}

MuellerResponse VGrooveLobe::eval_mueller(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return depolarizing_response(SampledSpectrum(0.0f), wo, wi);
}

SampledSpectrum VGrooveLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  if (facet_.mirror) return SampledSpectrum(1.0f);
  return fresnel_conductor(std::fabs(wo.z), facet_.n, facet_.k);
}

}  // namespace ochre
