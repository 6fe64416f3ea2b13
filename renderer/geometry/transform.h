#pragma once
// Transform: an affine 4x4 matrix (row-major storage, points as column vectors: p' = M p),
// and the parser for the scene file's "transform" values. The matrix is held and applied in double
// precision, and a point is rounded to single precision once, at the end: a scene placed at georeferenced
// coordinates (a translation of 5e6 composed with a shift back to the rendering origin,
// docs/scene-format.md, "Coordinate range") keeps every digit its vertices have.

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "materials/core/vec3.h"
#include "materials/core/vec3d.h"

namespace ochre {

struct Transform {
  // m[4 * row + column]; the bottom row is (0, 0, 0, 1) for every transform built here.
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  static Transform identity() { return {}; }
  static Transform translate(Vec3d offset);
  static Transform scale(Vec3d factors);
  // Right-handed rotation (counter-clockwise looking down the axis towards the origin) by
  // `degrees` about `axis` (any non-zero length; throws std::invalid_argument on zero).
  static Transform rotate(double degrees, Vec3 axis);
  // Camera-to-world transform of a viewer at `eye` looking at `target`. Camera space: the
  // camera looks along +z, +y is up and +x is right (as seen in the image). Columns of the
  // matrix are right = normalize(cross(forward, up)), the re-orthogonalized up, forward, eye.
  // With +x right, +y up, +z forward the camera frame is left-handed, so this transform has
  // determinant -1 and flips_handedness() is true (meshes placed with it get their winding
  // flipped by Mesh::transform so that normals stay consistent). Throws std::invalid_argument
  // when eye == target or up is parallel to the view direction.
  static Transform look_at(Vec3d eye, Vec3d target, Vec3d up);

  // (A * B) applies B first, then A.
  Transform operator*(const Transform& other) const;
  // Throws std::invalid_argument when the matrix is singular.
  Transform inverse() const;

  // In double precision, rounded to single precision once.
  Vec3 point(Vec3 p) const;
  Vec3 vector(Vec3 v) const;
  Vec3d point_double(const Vec3d& p) const;
  // Normal transformed by the inverse transpose of the 3x3 part, normalized.
  Vec3 normal(Vec3 n) const;

  // Determinant of the 3x3 linear part.
  float determinant3() const;
  bool flips_handedness() const { return determinant3() < 0.0f; }

  double operator()(int row, int column) const { return m[4 * row + column]; }
  double& operator()(int row, int column) { return m[4 * row + column]; }
};

// Parses a scene "transform" value. Accepted forms:
//   [16 numbers]                          a row-major matrix (bottom row must be 0 0 0 1)
//   [op, op, ...]                         operations applied to the object in the listed order
//   op                                    a single operation
// where each op is an object with exactly one key:
//   {"translate": [x, y, z]}, {"scale": s | [x, y, z]},
//   {"rotate": {"axis": [x, y, z], "angle": degrees}}, {"matrix": [16 numbers]},
//   {"look_at": {"eye": [..], "target": [..], "up": [..]}}   (Transform::look_at)
// "Applied in order" means [A, B] yields B * A: A acts on the object first.
// Errors (wrong types, non-finite numbers, zero scale or axis, singular or projective matrix)
// throw InputError whose message starts with `where` and the element, e.g.
// "scene.json: shapes[2].transform[1].rotate.axis: ...".
Transform parse_transform(const nlohmann::json& value, const std::string& where);

}  // namespace ochre
