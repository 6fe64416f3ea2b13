#pragma once
// The groove frame of an anisotropic groove lobe: x along the grooves (a unit vector of the local tangent
// plane), y = cross(z, x) across them, z the normal; and the LobeSample of a traced groove path, shared
// by the analytic (vgroove_lobe.h) and explicit (microgroove_lobe.h) groove lobes.

#include <array>

#include "materials/core/vec3d.h"
#include "materials/lobes/lobe.h"
#include "materials/lobes/reflection_chain.h"

namespace ochre {

// Facet material per hero wavelength: complex index n - i k, or an ideal mirror.
struct FacetSpectrum {
  SampledSpectrum n{1.5f}, k{0.0f};
  bool mirror = false;

  FacetIndex at(int wavelength) const {
    return mirror ? FacetIndex::ideal_mirror() : FacetIndex::conductor(n[wavelength], k[wavelength]);
  }
};

class GrooveFrame {
 public:
  explicit GrooveFrame(const Vec3& axis);  // axis in the local tangent plane (its z is ignored)

  Vec3d to_groove(const Vec3& v) const { return {dot(Vec3d(v), axis_), dot(Vec3d(v), across_), double(v.z)}; }
  Vec3 from_groove(const Vec3d& v) const {
    return (axis_ * v.x + across_ * v.y + Vec3d(0, 0, v.z)).to_float();
  }

 private:
  Vec3d axis_, across_;
};

// One ChainResponse per hero wavelength.
using GrooveResponses = std::array<ChainResponse, kSpectrumSamples>;
GrooveResponses groove_responses(ChainModel model, const FacetSpectrum& facet);

inline bool groove_model_polarizes(ChainModel model) {
  return model == ChainModel::kRigorous || model == ChainModel::kSeparateSP;
}

// The delta sample of a path that leaves the grooves along `exit` (groove frame) with the chain's
// responses and frames: weight = reflectance per wavelength, and for polarizing models the Mueller
// matrices between the chain's first and last s axes.
LobeSample groove_sample(const GrooveFrame& frame, const Vec3d& exit, const ChainFrames& chain,
                         const GrooveResponses& responses, bool polarizing);

}  // namespace ochre
