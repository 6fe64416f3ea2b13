// A field of view given across another film axis (camera.fov_axis, Mitsuba's fov_axis) is the same
// pinhole camera: the tangents of the half-angles scale with the film extents.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/camera/camera.h"

namespace ochre::camera_fov_axis_test {
namespace {

double degrees(double radians) {
  return radians * 180.0 / M_PI;
}

TEST(CameraFovAxis, ConvertsToTheShorterAxis) {
  // 200 x 100: 90 degrees across x is tan 45 * 100 / 200 across y.
  EXPECT_NEAR(fov_across_shorter_axis(90.0, FovAxis::X, 200, 100), 2 * degrees(std::atan(0.5)), 1e-12);
  EXPECT_NEAR(fov_across_shorter_axis(90.0, FovAxis::Larger, 200, 100), 2 * degrees(std::atan(0.5)), 1e-12);
  EXPECT_EQ(fov_across_shorter_axis(90.0, FovAxis::Y, 200, 100), 90.0);
  EXPECT_EQ(fov_across_shorter_axis(37.5, FovAxis::Smaller, 200, 100), 37.5);
  // Portrait: x is the shorter axis.
  EXPECT_NEAR(fov_across_shorter_axis(60.0, FovAxis::X, 100, 200), 60.0, 1e-12);
  EXPECT_NEAR(fov_across_shorter_axis(60.0, FovAxis::Y, 100, 200),
              2 * degrees(std::atan(std::tan(M_PI / 6) / 2)), 1e-12);
  // The diagonal of a 3 x 4 film is 5.
  EXPECT_NEAR(fov_across_shorter_axis(90.0, FovAxis::Diagonal, 300, 400), 2 * degrees(std::atan(0.6)), 1e-12);
}

TEST(CameraFovAxis, TheFilmEdgeSeesTheGivenAngle) {
  // Across x: the ray through the film's right edge (at mid-height) leaves at half the angle from the axis.
  const CameraBasis basis = camera_basis_look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
  const int w = 320, h = 200;
  const Camera camera =
      Camera::perspective(basis, static_cast<float>(fov_across_shorter_axis(70.0, FovAxis::X, w, h)), w, h);
  const Vec3 edge = normalize(camera.generate_ray(static_cast<float>(w), h / 2.0f).dir);
  EXPECT_NEAR(degrees(std::acos(-edge.z)), 35.0, 1e-3);
}

}  // namespace
}  // namespace ochre::camera_fov_axis_test
