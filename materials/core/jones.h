#pragma once
// Jones matrices (2x2 complex, double precision) acting on the field components (E_x, E_y) of a beam in
// a Stokes reference frame (x axis perpendicular to the propagation direction d, y = cross(d, x); see
// materials/core/stokes.h), and their conversion to Mueller matrices. A chain of specular reflections
// is a product of Jones matrices; converting once at the end is cheaper and more precise than
// multiplying Mueller matrices, and exact for non-depolarizing systems.

#include <complex>

#include "materials/core/mueller.h"

namespace ochre {

struct Jones {
  std::complex<double> a{1.0}, b{0.0}, c{0.0}, d{1.0};  // [[a, b], [c, d]]

  static Jones diagonal(std::complex<double> x, std::complex<double> y) { return {x, 0.0, 0.0, y}; }
  // Re-expresses the field in the frame whose x axis is the old one turned by theta towards y (the
  // Jones form of rotator(theta) in mueller.h).
  static Jones frame_rotation(double theta) {
    const double co = std::cos(theta), si = std::sin(theta);
    return {co, si, -si, co};
  }
};

inline Jones operator*(const Jones& p, const Jones& q) {
  return {p.a * q.a + p.b * q.c, p.a * q.b + p.b * q.d, p.c * q.a + p.d * q.c, p.c * q.b + p.d * q.d};
}

// Transmitted power for unpolarized light: (|a|^2 + |b|^2 + |c|^2 + |d|^2) / 2 (Mueller M00).
inline double unpolarized_gain(const Jones& j) {
  return 0.5 * (std::norm(j.a) + std::norm(j.b) + std::norm(j.c) + std::norm(j.d));
}

// The Mueller matrix of a Jones matrix, with the Stokes conventions of stokes.h (S2 = 2 Re(Ex Ey*),
// S3 = -2 Im(Ex Ey*)): column k is the image of the k-th unit Stokes vector through the coherency
// matrix C' = J C J^H, which is linear in the Stokes vector.
Mueller jones_to_mueller(const Jones& j);

}  // namespace ochre
