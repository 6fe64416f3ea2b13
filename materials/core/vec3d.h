#pragma once
// Double-precision 3D vectors for geometry that must stay exact over long chains of operations
// (a ray reflected a hundred times inside a narrow V-groove, reference integrations); the renderer's
// per-sample math is in Vec3 (float).

#include <cmath>

#include "materials/core/vec3.h"

namespace ochre {

struct Vec3d {
  double x = 0, y = 0, z = 0;

  constexpr Vec3d() = default;
  constexpr Vec3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  explicit constexpr Vec3d(const Vec3& v) : x(v.x), y(v.y), z(v.z) {}

  constexpr Vec3d operator-() const { return {-x, -y, -z}; }
  friend constexpr Vec3d operator+(const Vec3d& a, const Vec3d& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend constexpr Vec3d operator-(const Vec3d& a, const Vec3d& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend constexpr Vec3d operator*(const Vec3d& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3d operator*(double s, const Vec3d& a) { return a * s; }
  friend constexpr bool operator==(const Vec3d&, const Vec3d&) = default;

  Vec3 to_float() const { return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)}; }
};

constexpr double dot(const Vec3d& a, const Vec3d& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3d& v) {
  return std::sqrt(dot(v, v));
}
inline Vec3d normalize(const Vec3d& v) {
  return v * (1.0 / length(v));
}
// Mirror reflection of a propagation direction d off a plane with unit normal n.
constexpr Vec3d reflect(const Vec3d& d, const Vec3d& n) {
  return d - n * (2.0 * dot(d, n));
}

}  // namespace ochre
