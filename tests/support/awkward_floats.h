#pragma once
// Floats that break naive lookups (std::clamp passes NaN through; float -> int of NaN, infinities or
// values beyond the int range is undefined): NaN, the infinities, huge values whose products overflow, the
// first float without a fraction (2^23), signed zero, the smallest subnormal.

#include <limits>
#include <vector>

namespace ochre::test {

inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr float kLargest = std::numeric_limits<float>::max();
inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

inline std::vector<float> awkward_floats() {
  return {kNaN, kInf, -kInf, 1e30f, -1e30f, 3e38f, kLargest, -kLargest, 8388608.0f, -0.0f, 1e-45f};
}

}  // namespace ochre::test
