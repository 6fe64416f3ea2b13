#pragma once
// Mat3: a small row-major 3x3 matrix of doubles for colorimetric transforms (RGB <-> XYZ,
// chromatic adaptation). Header-only so the build-time table generator can use it too.
//
//   Mat3{{...9 values row by row...}}, Mat3::identity(), Mat3::diagonal(a, b, c),
//   m(row, col), m * n, m * Vec3, m.inverse() (throws std::domain_error when singular)

#include <array>
#include <cmath>
#include <stdexcept>

namespace ochre {

using Array3d = std::array<double, 3>;

struct Mat3 {
  std::array<double, 9> m{};

  static constexpr Mat3 identity() { return diagonal(1.0, 1.0, 1.0); }
  static constexpr Mat3 diagonal(double a, double b, double c) { return {{a, 0, 0, 0, b, 0, 0, 0, c}}; }

  constexpr double operator()(int row, int col) const { return m[row * 3 + col]; }
  constexpr double& operator()(int row, int col) { return m[row * 3 + col]; }

  friend constexpr Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r(i, j) = a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
    return r;
  }
  friend constexpr Array3d operator*(const Mat3& a, const Array3d& v) {
    return {a(0, 0) * v[0] + a(0, 1) * v[1] + a(0, 2) * v[2],
            a(1, 0) * v[0] + a(1, 1) * v[1] + a(1, 2) * v[2],
            a(2, 0) * v[0] + a(2, 1) * v[1] + a(2, 2) * v[2]};
  }

  constexpr double determinant() const {
    return (*this)(0, 0) * ((*this)(1, 1) * (*this)(2, 2) - (*this)(1, 2) * (*this)(2, 1)) -
           (*this)(0, 1) * ((*this)(1, 0) * (*this)(2, 2) - (*this)(1, 2) * (*this)(2, 0)) +
           (*this)(0, 2) * ((*this)(1, 0) * (*this)(2, 1) - (*this)(1, 1) * (*this)(2, 0));
  }

  // Inverse by the adjugate (cofactors), fine for the well-conditioned matrices of colorimetry.
  Mat3 inverse() const {
    const double det = determinant();
    if (det == 0.0 || !std::isfinite(det)) throw std::domain_error("Mat3::inverse: singular matrix");
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        // Cofactor of element (j, i): the cyclic index trick gives the sign for free.
        const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        r(i, j) = ((*this)(r0, c0) * (*this)(r1, c1) - (*this)(r0, c1) * (*this)(r1, c0)) / det;
      }
    return r;
  }
};

}  // namespace ochre
