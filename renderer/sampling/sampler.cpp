#include "renderer/sampling/sampler.h"

namespace ochre {

// Chain the mixes so that (seed, pixel, sample) triples never collide in practice.
IndependentSampler::IndependentSampler(uint64_t pixel_base, uint64_t sample_index, struct FromPixelBase)
    : pixel_base_(pixel_base),
      sample_index_(sample_index),
      key_(mix64(pixel_base ^ (sample_index * 0xd1b54a32d192ed03ull))) {}

IndependentSampler::IndependentSampler(uint64_t seed, uint64_t pixel_index, uint64_t sample_index)
    : IndependentSampler(mix64(mix64(seed + 0x9e3779b97f4a7c15ull) ^ pixel_index), sample_index,
                         FromPixelBase{}) {}

IndependentSampler IndependentSampler::branch(uint32_t j, uint32_t k) const {
  return IndependentSampler(mix64(pixel_base_ ^ kBranchStream), sample_index_ * k + j, FromPixelBase{});
}

float IndependentSampler::get_1d(uint32_t dimension) const {
  const uint64_t bits = mix64(key_ ^ (static_cast<uint64_t>(dimension) + 1) * 0x9e3779b97f4a7c15ull);
  return static_cast<float>(bits >> 40) * 0x1p-24f;  // 24 bits: exactly representable, < 1
}

}  // namespace ochre
