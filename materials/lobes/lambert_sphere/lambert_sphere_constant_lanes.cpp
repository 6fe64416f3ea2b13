#include "materials/lobes/lambert_sphere/lambert_sphere_constant_lanes.h"

#include <algorithm>

namespace ochre {

// Flattened (everything it calls inlined), so the loop is one body the compiler can vectorize; built twice,
// for AVX2 (eight lanes per instruction) and for any x86-64 (four), and chosen when the program starts. The
// two give the same bits: the same single-precision operations in the same order, lane by lane.
#define OCHRE_LANE_LOOP [[gnu::flatten, gnu::target_clones("avx2", "default")]]

OCHRE_LANE_LOOP LambertSphereConstantLanes
lambert_sphere_constant_lanes(std::span<const float, kSpectrumSamples> c, bool with_fast_variant) {
  LambertSphereConstantLanes lanes;
  if (with_fast_variant)  // two loops, each without a branch
    for (int k = 0; k < kSpectrumSamples; ++k) lanes.set(k, lambert_sphere_constants(c[k], true));
  else
    for (int k = 0; k < kSpectrumSamples; ++k) lanes.set(k, lambert_sphere_constants(c[k], false));
  return lanes;
}

OCHRE_LANE_LOOP void lambert_sphere_full_lanes(const LambertSphereConstantLanes& k,
                                               const LambertSphereGeometry<float>& g,
                                               std::span<float, kSpectrumSamples> f) {
  float values[kSpectrumSamples];  // not f: it might alias k or g, which would split the loop in two versions
  for (int i = 0; i < kSpectrumSamples; ++i) values[i] = lambert_sphere_full_valid(k.at(i), g);
  std::copy(values, values + kSpectrumSamples, f.begin());
}

#undef OCHRE_LANE_LOOP

}  // namespace ochre
