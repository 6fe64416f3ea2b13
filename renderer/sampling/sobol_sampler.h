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
// independent sampling (measured in tests/renderer/sampling/sobol_sampler_test.cpp).
//
// The Sobol sequence is 32-bit: the low 32 bits of the sample index pick the point, the high bits
// select a different scramble, so indices beyond 2^32 do not repeat points.

#include <cstdint>

#include "materials/core/vec3.h"
#include "renderer/sampling/sampler.h"

namespace ochre {

// The sampler is defined inline: it is called several times per path vertex.
namespace sobol_detail {

// Bits within each byte reversed by three swaps, then the byte order by one bswap instruction.
inline constexpr uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  return __builtin_bswap32(x);
}

// Sobol dimension 1 multiplies the index bits by the upper triangular Pascal matrix mod 2,
// C[i][j] = binomial(j, i) mod 2 (output digit i, most significant first; index bit j). By Lucas'
// theorem binomial(j, i) is odd iff the bits of i are a subset of the bits of j, so digit i is the
// xor of the index bits at all supersets j of i: a superset-sum (zeta) transform over GF(2),
// computed with one masked shift per bit of the position instead of a loop over 32 columns.
inline constexpr uint32_t pascal_matrix_times(uint32_t index) {
  index ^= (index >> 1) & 0x55555555u;  // positions whose bit 0 is clear take the one with it set
  index ^= (index >> 2) & 0x33333333u;
  index ^= (index >> 4) & 0x0f0f0f0fu;
  index ^= (index >> 8) & 0x00ff00ffu;
  index ^= (index >> 16) & 0x0000ffffu;
  return index;  // bit i holds output digit i
}

// Laine-Karras style permutation (Laine and Karras 2011, "Stratified sampling for stochastic
// transparency"), with the constants of N. Vegdahl, "Building a Better LK Hash" (2021), as also
// used by pbrt-v4's FastOwenScrambler. It acts on bit-reversed values: every step (adding,
// multiplying by an odd number, xor with a multiple by an even number) changes bit k only as a
// function of bits below it, and is a bijection - exactly the structure of a nested scramble.
inline constexpr uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

inline constexpr float to_unit_float(uint32_t fraction) {
  return static_cast<float>(fraction >> 8) * 0x1p-24f;  // 24 bits: exact in a float, < 1
}

}  // namespace sobol_detail

class SobolSampler {
 public:
  SobolSampler(uint64_t seed, uint64_t pixel_index, uint64_t sample_index);

  // Uniform number in [0, 1) (24 bits) for a given dimension: scrambled van der Corput point.
  // Equals get_2d(dimension).x.
  float get_1d(uint32_t dimension) const;
  // Point of the scrambled 2D Sobol (0,2)-sequence owned by `dimension` (the layout of
  // SampleDims reserves dimension and dimension + 1 for it).
  Vec2 get_2d(uint32_t dimension) const;
  // The numbers of branch j of the k continuations of this sample (PathIntegrator, integrator.branches):
  // index (this index) x k + j of the pixel's branch stream, a second stream with scrambles of its own, so
  // no branch shares a number with a camera sample's path (which may use the same dimensions, e.g. behind
  // a mirror). Still a pure function of (seed, pixel, sample index, dimension).
  SobolSampler branch(uint32_t j, uint32_t k) const;

 private:
  SobolSampler(uint64_t pixel_base, uint64_t sample_index, struct FromPixelBase);
  struct DimensionScramble {
    uint32_t shuffled_index;  // sample index after the per-dimension shuffle
    uint64_t hash;            // source of the two coordinate scramble seeds
  };
  DimensionScramble scramble_for(uint32_t dimension) const;

  uint64_t pixel_base_;  // hash of (seed, pixel)
  uint64_t sample_index_;
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

inline SobolSampler::SobolSampler(uint64_t pixel_base, uint64_t sample_index, struct FromPixelBase)
    : pixel_base_(pixel_base),
      sample_index_(sample_index),
      pixel_key_(mix64(pixel_base ^ (sample_index >> 32))),
      reversed_index_(sobol_detail::reverse_bits(static_cast<uint32_t>(sample_index))) {}

inline SobolSampler::SobolSampler(uint64_t seed, uint64_t pixel_index, uint64_t sample_index)
    : SobolSampler(mix64(mix64(seed ^ 0x6a09e667f3bcc909ull) ^ pixel_index), sample_index, FromPixelBase{}) {}

inline SobolSampler SobolSampler::branch(uint32_t j, uint32_t k) const {
  return SobolSampler(mix64(pixel_base_ ^ kBranchStream), sample_index_ * k + j, FromPixelBase{});
}

inline SobolSampler::DimensionScramble SobolSampler::scramble_for(uint32_t dimension) const {
  const uint64_t hash = mix64(pixel_key_ ^ (static_cast<uint64_t>(dimension) + 1) * 0x9e3779b97f4a7c15ull);
  // The shuffle is itself a nested scramble of the index bits (most significant first),
  // owen_scramble(index, seed), so it maps aligned blocks of 2^m indices onto aligned blocks
  // (Burley 2020, section 4).
  const uint32_t shuffled = sobol_detail::reverse_bits(
      sobol_detail::laine_karras_permutation(reversed_index_, static_cast<uint32_t>(hash)));
  return {shuffled, hash};
}

inline float SobolSampler::get_1d(uint32_t dimension) const {
  const DimensionScramble s = scramble_for(dimension);
  const uint32_t seed_x = static_cast<uint32_t>(s.hash >> 32);
  return sobol_detail::to_unit_float(
      sobol_detail::reverse_bits(sobol_detail::laine_karras_permutation(s.shuffled_index, seed_x)));
}

inline Vec2 SobolSampler::get_2d(uint32_t dimension) const {
  const DimensionScramble s = scramble_for(dimension);
  const uint32_t seed_x = static_cast<uint32_t>(s.hash >> 32);
  const uint32_t seed_y = static_cast<uint32_t>(mix64(s.hash));
  return {sobol_detail::to_unit_float(
              sobol_detail::reverse_bits(sobol_detail::laine_karras_permutation(s.shuffled_index, seed_x))),
          sobol_detail::to_unit_float(sobol_detail::reverse_bits(sobol_detail::laine_karras_permutation(
              sobol_detail::pascal_matrix_times(s.shuffled_index), seed_y)))};
}

}  // namespace ochre
