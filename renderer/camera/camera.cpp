#include "renderer/camera/camera.h"

#include <algorithm>
#include <cmath>

namespace ochre {

CameraBasis camera_basis_look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  CameraBasis b;
  b.eye = eye;
  b.forward = normalize(target - eye);
  b.right = normalize(cross(b.forward, up));
  b.up = cross(b.right, b.forward);
  return b;
}

double fov_across_shorter_axis(double fov_degrees, FovAxis axis, int width, int height) {
  if (axis == FovAxis::Smaller) return fov_degrees;
  // The tangents of the half-angles scale with the film extents (a pinhole's image plane).
  const double shorter = std::min(width, height), w = width, h = height;
  double extent = shorter;
  switch (axis) {
    case FovAxis::X:
      extent = w;
      break;
    case FovAxis::Y:
      extent = h;
      break;
    case FovAxis::Diagonal:
      extent = std::sqrt(w * w + h * h);
      break;
    case FovAxis::Larger:
      extent = std::max(w, h);
      break;
    case FovAxis::Smaller:
      break;
  }
  const double half = std::tan(0.5 * fov_degrees * M_PI / 180.0) * shorter / extent;
  return 2.0 * std::atan(half) * 180.0 / M_PI;
}

namespace {
// Half extents of the film for a given half-extent of its shorter axis.
void film_half_extents(float shorter_half, int width, int height, float& hw, float& hh) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  if (width >= height) {
    hh = shorter_half;
    hw = shorter_half * aspect;
  } else {
    hw = shorter_half;
    hh = shorter_half / aspect;
  }
}
}  // namespace

Camera Camera::perspective(const CameraBasis& basis, float fov_degrees, int width, int height) {
  Camera c;
  c.kind_ = Kind::Perspective;
  c.basis_ = basis;
  c.width_ = width;
  c.height_ = height;
  film_half_extents(std::tan(0.5f * fov_degrees * kPi / 180.0f), width, height, c.half_width_,
                    c.half_height_);
  return c;
}

Camera Camera::orthographic(const CameraBasis& basis, float view_size, int width, int height) {
  Camera c;
  c.kind_ = Kind::Orthographic;
  c.basis_ = basis;
  c.width_ = width;
  c.height_ = height;
  film_half_extents(0.5f * view_size, width, height, c.half_width_, c.half_height_);
  return c;
}

RayCone Camera::pixel_cone() const {
  const float pixel = 2.0f * half_height_ / static_cast<float>(height_);
  return kind_ == Kind::Perspective ? RayCone{0.0f, pixel} : RayCone{pixel, 0.0f};
}

Ray Camera::generate_ray(float film_x, float film_y) const {
  const float sx = (2.0f * film_x / static_cast<float>(width_) - 1.0f) * half_width_;
  const float sy = (1.0f - 2.0f * film_y / static_cast<float>(height_)) * half_height_;
  Ray ray;
  if (kind_ == Kind::Perspective) {
    ray.origin = basis_.eye;
    ray.dir = normalize(basis_.forward + basis_.right * sx + basis_.up * sy);
  } else {
    ray.origin = basis_.eye + basis_.right * sx + basis_.up * sy;
    ray.dir = basis_.forward;
  }
  return ray;
}

}  // namespace ochre
