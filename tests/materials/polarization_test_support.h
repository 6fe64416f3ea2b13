#pragma once
// Helpers for the polarization tests of lobes: world-space polarization directions <-> Stokes vectors
// in a lobe's MuellerResponse frames (x axis given, y = cross(d, x)), and direction helpers.

#include <gtest/gtest.h>

#include <cmath>

#include "materials/lobes/lobe.h"

namespace ochre::test {

inline Vec3 direction(float theta, float phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Fully linearly polarized light of unit intensity whose electric field oscillates along the world
// direction e (perpendicular to the propagation direction d), in the frame (x, cross(d, x)).
inline Stokes linear_stokes(const Vec3& e, const Vec3& d, const Vec3& x) {
  const float psi = std::atan2(dot(e, cross(d, x)), dot(e, x));
  return {{1.0f, std::cos(2 * psi), std::sin(2 * psi), 0.0f}};
}

// The world direction of the linear polarization of s (frame (x, cross(d, x))), up to sign.
inline Vec3 polarization_direction(const Stokes& s, const Vec3& d, const Vec3& x) {
  const float psi = 0.5f * std::atan2(s[2], s[1]);
  return x * std::cos(psi) + cross(d, x) * std::sin(psi);
}

// Every entry of a Mueller matrix within tol of the expected one.
inline void expect_mueller(const Mueller& got, const Mueller& want, float tol = 1e-6f) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got(r, c), want(r, c), tol) << "entry " << r << "," << c;
}

inline bool all_finite(const Mueller& m) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(m(r, c))) return false;
  return true;
}

inline bool all_finite(const SampledSpectrum& s) {
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (!std::isfinite(s[i])) return false;
  return true;
}

// The frames of a response are valid: unit x axes perpendicular to their beams.
inline ::testing::AssertionResult valid_frames(const MuellerResponse& r, const Vec3& wo, const Vec3& wi) {
  if (std::fabs(length(r.in_x) - 1.0f) > 1e-5f || std::fabs(length(r.out_x) - 1.0f) > 1e-5f)
    return ::testing::AssertionFailure() << "axes not unit";
  if (std::fabs(dot(r.in_x, wi)) > 1e-5f || std::fabs(dot(r.out_x, wo)) > 1e-5f)
    return ::testing::AssertionFailure() << "axes not perpendicular to their beams";
  return ::testing::AssertionSuccess();
}

}  // namespace ochre::test
