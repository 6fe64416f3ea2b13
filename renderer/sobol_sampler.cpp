#include "renderer/sobol_sampler.h"

#include "renderer/sampler.h"

namespace ochre {
namespace {

// Bits within each byte reversed by three swaps, then the byte order by one bswap instruction.
constexpr uint32_t reverse_bits(uint32_t x) {
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
constexpr uint32_t pascal_matrix_times(uint32_t index) {
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
constexpr uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

constexpr float to_unit_float(uint32_t fraction) {
  return static_cast<float>(fraction >> 8) * 0x1p-24f;  // 24 bits: exact in a float, < 1
}

}  // namespace

uint32_t sobol_dimension0(uint32_t index) {
  return reverse_bits(index);
}

uint32_t sobol_dimension1(uint32_t index) {
  return reverse_bits(pascal_matrix_times(index));  // digit 0 becomes the most significant bit
}

uint32_t owen_scramble(uint32_t value, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(value), seed));
}

// The sampler composes the functions above without the bit reversals that cancel:
// owen_scramble(sobol_dimension0(i), s) = reverse(LK(i, s)) and
// owen_scramble(sobol_dimension1(i), s) = reverse(LK(pascal(i), s)).

SobolSampler::SobolSampler(uint64_t seed, uint64_t pixel_index, uint64_t sample_index)
    : pixel_key_(mix64(mix64(mix64(seed ^ 0x6a09e667f3bcc909ull) ^ pixel_index) ^ (sample_index >> 32))),
      reversed_index_(reverse_bits(static_cast<uint32_t>(sample_index))) {}

SobolSampler::DimensionScramble SobolSampler::scramble_for(uint32_t dimension) const {
  const uint64_t hash = mix64(pixel_key_ ^ (static_cast<uint64_t>(dimension) + 1) * 0x9e3779b97f4a7c15ull);
  // The shuffle is itself a nested scramble of the index bits (most significant first),
  // owen_scramble(index, seed), so it maps aligned blocks of 2^m indices onto aligned blocks
  // (Burley 2020, section 4).
  const uint32_t shuffled =
      reverse_bits(laine_karras_permutation(reversed_index_, static_cast<uint32_t>(hash)));
  return {shuffled, hash};
}

float SobolSampler::get_1d(uint32_t dimension) const {
  const DimensionScramble s = scramble_for(dimension);
  const uint32_t seed_x = static_cast<uint32_t>(s.hash >> 32);
  return to_unit_float(reverse_bits(laine_karras_permutation(s.shuffled_index, seed_x)));
}

Vec2 SobolSampler::get_2d(uint32_t dimension) const {
  const DimensionScramble s = scramble_for(dimension);
  const uint32_t seed_x = static_cast<uint32_t>(s.hash >> 32);
  const uint32_t seed_y = static_cast<uint32_t>(mix64(s.hash));
  return {
      to_unit_float(reverse_bits(laine_karras_permutation(s.shuffled_index, seed_x))),
      to_unit_float(reverse_bits(laine_karras_permutation(pascal_matrix_times(s.shuffled_index), seed_y)))};
}

}  // namespace ochre
