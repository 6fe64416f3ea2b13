#pragma once
// Padded, Owen-scrambled Sobol sampler (low-discrepancy sibling of IndependentSampler).
//
// Every get_2d(dimension) pair is its own 2D Sobol (0,2)-sequence, every get_1d(dimension) its own
// van der Corput sequence ("padding", as pbrt-v4's PaddedSobolSampler, Pharr et al. 2023, 8.7.3).
// Per (seed, pixel, dimension) each coordinate gets an independent hash-based nested uniform
// (Owen) scramble, and the sample index is shuffled with a nested uniform scramble of its bits
// (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4), section 4). Without that
// shuffle, two padded dimensions would be two scrambles of the same van der Corput point, i.e. a
// scrambled diagonal: fine per dimension, badly correlated across dimensions.
//
// Decision on the index shuffle: it is a fixed bijection of the sample index per
// (seed, pixel, dimension), so every number stays a pure function of (seed, pixel, sample index,
// dimension) and images do not depend on the thread count or on how the sample range is split.
// The shuffle maps every aligned block of 2^m indices onto an aligned block of 2^m indices, so
// samples [0, 2^m) - and any aligned block [k 2^m, (k+1) 2^m) - of one pixel still form a
// scrambled (0,m,2)-net in each pair. Unlike pbrt it needs no sample count. The price: samples
// 2k and 2k+1 fall in opposite halves of every dimension, so an integrand coupling two different
// padded dimensions (e.g. a 2x2 checkerboard of two 1D dims) can see about twice the variance of
// independent sampling (measured in tests/renderer/test_sobol_sampler.cpp).
//
// The Sobol sequence is 32-bit: the low 32 bits of the sample index pick the point, the high bits
// select a different scramble, so indices beyond 2^32 do not repeat points.

#include <cstdint>

#include "materials/vec3.h"

namespace ochre {

class SobolSampler {
 public:
  SobolSampler(uint64_t seed, uint64_t pixel_index, uint64_t sample_index);

  // Uniform number in [0, 1) (24 bits) for a given dimension: scrambled van der Corput point.
  // Equals get_2d(dimension).x.
  float get_1d(uint32_t dimension) const;
  // Point of the scrambled 2D Sobol (0,2)-sequence owned by `dimension` (the layout of
  // SampleDims reserves dimension and dimension + 1 for it).
  Vec2 get_2d(uint32_t dimension) const;

 private:
  struct DimensionScramble {
    uint32_t shuffled_index;  // sample index after the per-dimension shuffle
    uint64_t hash;            // source of the two coordinate scramble seeds
  };
  DimensionScramble scramble_for(uint32_t dimension) const;

  uint64_t pixel_key_;       // hash of (seed, pixel, high bits of the sample index)
  uint32_t reversed_index_;  // low 32 bits of the sample index, bit-reversed
};

// Building blocks, exposed for tests. All values are 32-bit binary fractions (x / 2^32).

// Sobol dimension 0: van der Corput radical inverse in base 2 (bit reversal).
uint32_t sobol_dimension0(uint32_t index);
// Sobol dimension 1: generator matrix = upper triangular Pascal matrix mod 2.
uint32_t sobol_dimension1(uint32_t index);
// Hash-based nested uniform (Owen) scramble of a binary fraction: bit k (from the most
// significant) is flipped by a function of the seed and the bits above it only.
uint32_t owen_scramble(uint32_t value, uint32_t seed);

}  // namespace ochre
