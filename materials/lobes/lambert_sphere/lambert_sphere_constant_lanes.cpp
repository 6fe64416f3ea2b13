#include "materials/lobes/lambert_sphere/lambert_sphere_constant_lanes.h"

#include <algorithm>

#include "materials/core/vector_clones.h"

namespace ochre {

// Each loop one body, vectorized (materials/core/vector_clones.h).
OCHRE_VECTOR_CLONES LambertSphereConstantLanes
lambert_sphere_constant_lanes(std::span<const float, kSpectrumSamples> c, bool with_fast_variant) {
  LambertSphereConstantLanes lanes;
  if (with_fast_variant)  // two loops, each without a branch
    for (int k = 0; k < kSpectrumSamples; ++k) lanes.set(k, lambert_sphere_constants(c[k], true));
  else
    for (int k = 0; k < kSpectrumSamples; ++k) lanes.set(k, lambert_sphere_constants(c[k], false));
  return lanes;
}

OCHRE_VECTOR_CLONES void lambert_sphere_full_lanes(const LambertSphereConstantLanes& k,
                                                   const LambertSphereGeometry<float>& g,
                                                   std::span<float, kSpectrumSamples> f) {
  float values[kSpectrumSamples];  // not f: it might alias k or g, which would split the loop in two versions
  for (int i = 0; i < kSpectrumSamples; ++i) values[i] = lambert_sphere_full_valid(k.at(i), g);
  std::copy(values, values + kSpectrumSamples, f.begin());
}

}  // namespace ochre
