#pragma once
// Degrees in radians for the tests, in both precisions, beside pi (materials/core/pi.h). One definition for
// every test file: a test executable compiles its files together (unity build).

#include <numbers>

#include "materials/core/pi.h"

namespace ochre::test {

inline constexpr double kDegD = std::numbers::pi / 180.0;
inline constexpr float kDegF = std::numbers::pi_v<float> / 180.0f;

}  // namespace ochre::test
