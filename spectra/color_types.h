#pragma once
// Tristimulus value types: CIE 1931 XYZ and RGB in some working space (see color_space.h).

#include <cmath>

namespace ochre {

struct XYZ {
  float x = 0.0f, y = 0.0f, z = 0.0f;
  friend constexpr bool operator==(const XYZ&, const XYZ&) = default;
};

inline bool is_finite(const XYZ& c) {
  return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

struct RGB {
  float r = 0.0f, g = 0.0f, b = 0.0f;
  constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
  friend constexpr bool operator==(const RGB&, const RGB&) = default;
};

}  // namespace ochre
