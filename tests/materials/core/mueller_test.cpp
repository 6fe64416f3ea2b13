// Mueller algebra and elements: the check values of docs/polarization.md (rotator, Malus,
// depolarizer, polarizers, retarders) and the frame-change rotator stokes_basis_rotation().

#include "materials/core/mueller.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/core/pi.h"
#include "materials/polarization_test_support.h"
#include "support/spectrum_lanes.h"

namespace ochre::test::mueller_test {
namespace {

void expect_stokes(const Stokes& got, const Stokes& want, float tol = 1e-6f) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}

Vec3 rotate_about(const Vec3& v, const Vec3& axis, float angle) {  // Rodrigues
  return v * std::cos(angle) + cross(axis, v) * std::sin(angle) +
         axis * (dot(axis, v) * (1 - std::cos(angle)));
}

TEST(Mueller, ProductTransposeAndRowVectorAgreeWithDefinitions) {
  Mueller a, b;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      a(r, c) = float(r * 4 + c + 1);
      b(r, c) = float((r + 2) * (c + 1) % 7) - 3.0f;
    }
  const Mueller ab = a * b;
  EXPECT_FLOAT_EQ(ab(1, 2), a(1, 0) * b(0, 2) + a(1, 1) * b(1, 2) + a(1, 2) * b(2, 2) + a(1, 3) * b(3, 2));
  expect_mueller(transpose(a * b), transpose(b) * transpose(a));
  expect_mueller(Mueller::identity() * a, a);
  const Stokes s{{1.0f, -2.0f, 0.5f, 3.0f}};
  // s^T A = (A^T s)^T
  expect_stokes(s * a, transpose(a) * s);
  expect_stokes((a * b) * s, a * (b * s), 1e-4f);
  expect_mueller(a * 2.0f, absorber(2.0f) * a);
}

TEST(Mueller, RotatorMatchesTheNote) {
  // rotator(+45 deg)[1,1,0,0] = [1,0,-1,0]
  expect_stokes(rotator(45 * kDegF) * Stokes{{1, 1, 0, 0}}, Stokes{{1, 0, -1, 0}});
  // Rotations compose additively, and the inverse is the transpose.
  expect_mueller(rotator(0.3f) * rotator(0.5f), rotator(0.8f));
  expect_mueller(rotator(-0.7f), transpose(rotator(0.7f)));
  expect_mueller(rotator(kPi), Mueller::identity());
}

TEST(Mueller, MalusLawThroughARotatedPolarizer) {
  // A linear polarizer rotated by 30 deg passes S0 = cos^2(30 deg) = 0.75 of [1,1,0,0].
  const Stokes out = rotated_element(30 * kDegF, linear_polarizer()) * Stokes{{1, 1, 0, 0}};
  EXPECT_NEAR(out[0], 0.75f, 1e-6f);
  for (float theta : {0.0f, 0.2f, 1.0f, 2.5f}) {
    const Stokes o = rotated_element(theta, linear_polarizer()) * Stokes{{1, 1, 0, 0}};
    EXPECT_NEAR(o[0], std::cos(theta) * std::cos(theta), 1e-6f);
  }
}

TEST(Mueller, PolarizerAtFourAnglesOnUnpolarizedLight) {
  const Stokes unpolarized = Stokes::unpolarized(1.0f);
  expect_stokes(rotated_element(0, linear_polarizer()) * unpolarized, Stokes{{.5f, .5f, 0, 0}});
  expect_stokes(rotated_element(90 * kDegF, linear_polarizer()) * unpolarized, Stokes{{.5f, -.5f, 0, 0}});
  expect_stokes(rotated_element(45 * kDegF, linear_polarizer()) * unpolarized, Stokes{{.5f, 0, .5f, 0}});
  expect_stokes(rotated_element(-45 * kDegF, linear_polarizer()) * unpolarized, Stokes{{.5f, 0, -.5f, 0}});
}

TEST(Mueller, DepolarizerAndAbsorber) {
  expect_stokes(depolarizer(0.8f) * Stokes{{1, .5f, .5f, .5f}}, Stokes{{0.8f, 0, 0, 0}});
  expect_stokes(absorber(0.25f) * Stokes{{1, .5f, -.5f, .5f}}, Stokes{{.25f, .125f, -.125f, .125f}});
  const MuellerSpectrum d = depolarizer(lanes({0.1f, 0.2f, 0.3f, 0.4f}));
  EXPECT_FLOAT_EQ(d[2](0, 0), 0.3f);
  EXPECT_EQ(d[2](1, 1), 0.0f);
}

TEST(Mueller, QuarterAndHalfWaveRetarders) {
  const Mueller quarter = linear_retarder(0.5f * kPi), half = linear_retarder(kPi);
  expect_stokes(quarter * Stokes{{1, 0, 1, 0}}, Stokes{{1, 0, 0, -1}});
  expect_stokes(quarter * Stokes{{1, 0, 0, 1}}, Stokes{{1, 0, 1, 0}});
  expect_stokes(half * Stokes{{1, 0, 1, 0}}, Stokes{{1, 0, -1, 0}});
  expect_stokes(half * Stokes{{1, 0, -1, 0}}, Stokes{{1, 0, 1, 0}});
  // Linear light along the fast or slow axis passes unchanged.
  expect_stokes(quarter * Stokes{{1, 1, 0, 0}}, Stokes{{1, 1, 0, 0}});
  expect_stokes(quarter * Stokes{{1, -1, 0, 0}}, Stokes{{1, -1, 0, 0}});
}

TEST(StokesBasisRotation, ComposesAdditively) {
  const Vec3 d = normalize(Vec3(0.3f, -0.5f, 0.8f));
  const Vec3 x0 = normalize(cross(d, Vec3(1, 0, 0)));
  const float a = 0.4f, b = 1.1f;
  const Vec3 xa = rotate_about(x0, d, a), xab = rotate_about(x0, d, a + b);
  // The frame turned by a, then by b, is the frame turned by a + b (y = cross(d, x) turns with it).
  expect_mueller(stokes_basis_rotation(d, xa, xab) * stokes_basis_rotation(d, x0, xa),
                 stokes_basis_rotation(d, x0, xab), 2e-6f);
  expect_mueller(stokes_basis_rotation(d, x0, xa), rotator(a), 2e-6f);
  expect_mueller(stokes_basis_rotation(d, x0, xab), rotator(a + b), 2e-6f);
}

TEST(StokesBasisRotation, NinetyDegreesSwapsXAndYAndFlipsS1S2) {
  const Vec3 d(0, 0, 1), x(1, 0, 0), y = cross(d, x);
  // Light polarized along x: S1 = +1 in (x, y), -1 in the frame whose x axis is the old y.
  expect_stokes(stokes_basis_rotation(d, x, y) * Stokes{{1, 1, 0, 0}}, Stokes{{1, -1, 0, 0}});
  // +45 deg light (between x and y) is -45 deg in the new frame; circular light is untouched.
  expect_stokes(stokes_basis_rotation(d, x, y) * Stokes{{1, 0, 1, 0}}, Stokes{{1, 0, -1, 0}});
  expect_stokes(stokes_basis_rotation(d, x, y) * Stokes{{1, 0, 0, 1}}, Stokes{{1, 0, 0, 1}});
  // Turning by 45 deg: x-polarized light is at -45 deg from the new x.
  const Vec3 x45 = normalize(x + y);
  expect_stokes(stokes_basis_rotation(d, x, x45) * Stokes{{1, 1, 0, 0}}, Stokes{{1, 0, -1, 0}});
  // Reversing x (a rotation by 180 deg) changes nothing.
  expect_mueller(stokes_basis_rotation(d, x, -x), Mueller::identity(), 1e-6f);
}

TEST(StokesBasisRotation, ReframedElementActsTheSameOnTheSameLight) {
  // A polarizer at 30 deg from x on a beam along d, re-expressed in a frame turned by 0.9 rad: the
  // same world-space light gives the same world-space result.
  const Vec3 d = normalize(Vec3(-0.2f, 0.7f, 0.4f));
  const Vec3 x = normalize(cross(d, Vec3(0, 0, 1))), x2 = rotate_about(x, d, 0.9f);
  const Mueller m = rotated_element(30 * kDegF, linear_polarizer());
  const Mueller m2 = reframe_mueller(m, d, x, x2, d, x, x2);
  const Stokes in{{1, 0.3f, -0.5f, 0.2f}};  // given in frame x
  const Stokes in2 = stokes_basis_rotation(d, x, x2) * in;
  expect_stokes(m2 * in2, stokes_basis_rotation(d, x, x2) * (m * in), 2e-6f);
  expect_mueller(m2, rotated_element(30 * kDegF - 0.9f, linear_polarizer()), 2e-6f);
  const StokesSpectrum out = uniform_spectrum(m) * StokesSpectrum{in, in, in, in};
  expect_stokes(out[3], m * in);
}

TEST(StokesBasisRotation, DirectionsAlongTheAxesAndHandedness) {
  const Vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (const Vec3& d : axes) {
    // Two perpendiculars of d from the coordinate axes, exactly.
    const Vec3 e1 = std::fabs(d.x) > 0.5f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    const Vec3 e2 = cross(d, e1);  // e1 turned by +90 deg about d
    expect_mueller(stokes_basis_rotation(d, e1, e2), rotator(0.5f * kPi), 1e-6f);
    expect_mueller(stokes_basis_rotation(d, e2, e1), rotator(-0.5f * kPi), 1e-6f);
    const Vec3 diag = normalize(e1 + e2);
    const Mueller r = stokes_basis_rotation(d, e1, diag);
    expect_mueller(r, rotator(0.25f * kPi), 1e-6f);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(r(i, j)));
  }
}

TEST(StokesBasisRotation, IsContinuousWhereBranchyBasesJump) {
  // A nearly horizontal segment whose z component crosses zero by rounding (the note's V-groove
  // hazard): two frames that are geometrically opposite x axes must give the same rotator
  // (rotation by pi = identity) whatever the sign of the tiny z; a sign(z)-branching basis would not.
  for (float dz : {-1e-7f, -0.0f, 0.0f, 1e-7f}) {
    const Vec3 d = normalize(Vec3(1, 0, dz));
    const Vec3 x_from = normalize(Vec3(0, 0, 1) - d * dot(Vec3(0, 0, 1), d));
    const Vec3 x_to = cross(Vec3(0, 1, 0), d);  // (dz, 0, -1): the opposite of x_from
    expect_mueller(stokes_basis_rotation(d, x_from, x_to), Mueller::identity(), 1e-5f);
    // ... and a frame a quarter turn away gives the same rotator on both sides of dz = 0.
    expect_mueller(stokes_basis_rotation(d, x_from, cross(d, x_from)), rotator(0.5f * kPi), 1e-6f);
  }
}

}  // namespace
}  // namespace ochre::test::mueller_test
