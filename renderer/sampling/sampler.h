#pragma once
// Deterministic independent sampler: every number is a pure function of
// (seed, pixel, sample index, dimension), so an image does not depend on the thread count,
// the tile order or how the sample range is split (docs/architecture.md, 'Sampler and determinism').

#include <cstdint>

#include "materials/core/vec3.h"

namespace ochre {

// Fixed dimension layout of one camera sample. Every bounce owns kDimsPerBounce dimensions,
// so a path's random numbers never shift when an earlier event takes another branch.
struct SampleDims {
  static constexpr uint32_t kWavelength = 0;
  static constexpr uint32_t kPixelJitter = 1;  // 2 dims
  static constexpr uint32_t kFirstBounce = 3;
  static constexpr uint32_t kDimsPerBounce = 8;
  // Offsets inside a bounce.
  static constexpr uint32_t kLightChoice = 0;
  static constexpr uint32_t kLightPosition = 1;  // 2 dims
  static constexpr uint32_t kLobeChoice = 3;
  static constexpr uint32_t kLobeDirection = 4;  // 2 dims
  static constexpr uint32_t kRoulette = 6;
  // Light through a planar mirror (renderer/lights/planar_mirrors.h): its position reuses kLightPosition's
  // two numbers shifted by half a period, so scenes without mirrors keep every other number where it was.
  static constexpr uint32_t kMirrorLightChoice = 7;
  static constexpr uint32_t bounce(uint32_t depth, uint32_t offset) {
    return kFirstBounce + depth * kDimsPerBounce + offset;
  }
  // The position on light `light` when every light is sampled at a vertex (integrator.light_selection
  // "all"): the first light takes kLightPosition, each further one a pair of its own far beyond any bounce's.
  static constexpr uint32_t kExtraLightStride = 1u << 20;
  static constexpr uint32_t light_position(uint32_t depth, uint32_t light) {
    return bounce(depth, kLightPosition) + light * kExtraLightStride;
  }
};

struct FromPixelBase {};  // tag: constructor from the hash of (seed, pixel)
// Salt of a pixel's branch stream (Sampler::branch).
inline constexpr uint64_t kBranchStream = 0x5851f42d4c957f2dull;

class IndependentSampler {
 public:
  IndependentSampler(uint64_t seed, uint64_t pixel_index, uint64_t sample_index);

  // Uniform number in [0, 1) for a given dimension.
  float get_1d(uint32_t dimension) const;
  Vec2 get_2d(uint32_t dimension) const { return {get_1d(dimension), get_1d(dimension + 1)}; }
  // The numbers of branch j of the k continuations of this sample (PathIntegrator, integrator.branches):
  // index (this index) x k + j of the pixel's branch stream, a second stream with scrambles of its own, so
  // no branch shares a number with a camera sample's path (which may use the same dimensions, e.g. behind
  // a mirror). Still a pure function of (seed, pixel, sample index, dimension).
  IndependentSampler branch(uint32_t j, uint32_t k) const;

 private:
  IndependentSampler(uint64_t pixel_base, uint64_t sample_index, struct FromPixelBase);
  uint64_t pixel_base_;
  uint64_t sample_index_;
  uint64_t key_;
};

// 64-bit finaliser of SplitMix64 (Steele et al. 2014): a bijective avalanche mix.
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace ochre
