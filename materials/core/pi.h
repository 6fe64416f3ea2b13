#pragma once
// pi, and degrees in radians, in the precisions the code uses: float for the rendering math, double for
// the numerical models (tables, quadratures) that are computed once.

#include <numbers>

namespace ochre {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;
inline constexpr double kPiD = std::numbers::pi;
inline constexpr double kTwoPiD = 2.0 * std::numbers::pi;
inline constexpr double kDegD = std::numbers::pi / 180.0;
inline constexpr float kDegF = std::numbers::pi_v<float> / 180.0f;

}  // namespace ochre
