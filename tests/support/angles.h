#pragma once
// pi and degrees in radians for the tests, in both precisions (the libraries' ochre::kPi is a float). One
// definition for every test file: a test executable compiles its files together (unity build), where
// per-file copies in anonymous namespaces would collide.

#include <numbers>

namespace ochre::test {

inline constexpr double kPiD = std::numbers::pi;
inline constexpr double kDegD = std::numbers::pi / 180.0;
inline constexpr float kDegF = std::numbers::pi_v<float> / 180.0f;

}  // namespace ochre::test
