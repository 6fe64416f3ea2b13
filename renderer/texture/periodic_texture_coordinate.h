#pragma once
// A texture coordinate of a periodic lookup (period 1), made safe to turn into a texel index.
//
// From 2^23 on every float is an integer, so under a period of 1 it stands for the same place as 0; such
// a coordinate (up to the largest float, which times the texture's width overflows to infinity, and a
// float -> int conversion of that is undefined behaviour) is replaced by 0. Smaller coordinates are
// returned unchanged, so lookups anywhere else keep their exact values.

#include <cmath>

namespace ochre {

inline float periodic_texture_coordinate(float u) {
  constexpr float kFirstWithoutFraction = 8388608.0f;  // 2^23
  return std::fabs(u) < kFirstWithoutFraction ? u : 0.0f;
}

}  // namespace ochre
