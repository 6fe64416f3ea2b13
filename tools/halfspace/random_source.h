#pragma once
// Deterministic uniform random numbers for the half-space simulation. std::mt19937_64 is specified
// bit for bit by the C++ standard, so a seed gives the same walk on every platform; doubles are built
// from the top 53 bits directly (std::uniform_real_distribution is implementation-defined).

#include <cstdint>
#include <random>

namespace ochre::halfspace {

class RandomSource {
 public:
  // `stream` separates independent sequences for the same seed (one per block of paths).
  RandomSource(uint64_t seed, uint64_t stream) {
    std::seed_seq sequence{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                           static_cast<uint32_t>(stream), static_cast<uint32_t>(stream >> 32)};
    engine_.seed(sequence);
  }

  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace ochre::halfspace
