#include "materials/lobes/vgroove/groove_frame.h"

#include <cmath>
#include <utility>

namespace ochre {

GrooveFrame::GrooveFrame(const Vec3& axis) {
  const double len = std::hypot(double(axis.x), double(axis.y));
  axis_ = len > 0.0 ? Vec3d(axis.x / len, axis.y / len, 0.0) : Vec3d(1.0, 0.0, 0.0);
  across_ = {-axis_.y, axis_.x, 0.0};
}

namespace {
template <size_t... I>
GrooveResponses responses_per_lane(ChainModel model, const FacetSpectrum& facet, std::index_sequence<I...>) {
  return {ChainResponse(model, facet.at(I))...};
}
}  // namespace

GrooveResponses groove_responses(ChainModel model, const FacetSpectrum& facet) {
  return responses_per_lane(model, facet, std::make_index_sequence<kSpectrumSamples>());
}

LobeSample groove_sample(const GrooveFrame& frame, const Vec3d& exit, const ChainFrames& chain,
                         const GrooveResponses& responses, bool polarizing) {
  LobeSample s;
  s.wi = frame.from_groove(exit);
  if (!(s.wi.z > 0.0f)) s.wi.z = 1e-7f;  // a grazing exit rounded onto the horizon stays above it
  s.pdf = 1.0f;  // the uniform entry position makes the estimator unbiased; no MIS after a delta lobe
  s.delta = true;
  for (int i = 0; i < kSpectrumSamples; ++i) s.weight[i] = static_cast<float>(responses[i].reflectance());
  if (polarizing) {
    s.has_mueller = true;
    for (int i = 0; i < kSpectrumSamples; ++i) s.mueller.m[i] = responses[i].mueller();
    s.mueller.in_x = frame.from_groove(chain.first_s());
    s.mueller.out_x = frame.from_groove(chain.last_s());
  }
  return s;
}

}  // namespace ochre
