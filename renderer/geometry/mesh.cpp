#include "renderer/geometry/mesh.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "renderer/geometry/coordinate_limit.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

template <typename T>
void check_attribute(const std::vector<T>& values, size_t vertex_count, const char* what,
                     const std::string& where) {
  if (values.empty()) return;
  if (values.size() != vertex_count) {
    throw InputError(fmt::format("{}: {} {} for {} vertices (must be one per vertex or none)", where,
                                 values.size(), what, vertex_count));
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (!is_finite(values[i]))
      throw InputError(fmt::format("{}: {} of vertex {} is not finite", where, what, i));
  }
}

}  // namespace

float Mesh::triangle_area(size_t triangle) const {
  const Vec3& p0 = positions[indices[3 * triangle]];
  const Vec3& p1 = positions[indices[3 * triangle + 1]];
  const Vec3& p2 = positions[indices[3 * triangle + 2]];
  return 0.5f * length(cross(p1 - p0, p2 - p0));
}

Mesh::Bounds Mesh::bounds() const {
  Bounds b;
  for (const Vec3& p : positions) {
    b.lo = min(b.lo, p);
    b.hi = max(b.hi, p);
  }
  return b;
}

float Mesh::surface_area() const {
  double sum = 0;
  for (size_t i = 0; i < triangle_count(); ++i) sum += triangle_area(i);
  return static_cast<float>(sum);
}

void Mesh::transform(const Transform& to_world) {
  if (!normals.empty()) {
    // The inverse transpose, computed once for all normals (throws before any change when singular).
    const Transform inverse = to_world.inverse();
    for (Vec3& n : normals) {
      const Vec3d m{inverse(0, 0) * n.x + inverse(1, 0) * n.y + inverse(2, 0) * n.z,
                    inverse(0, 1) * n.x + inverse(1, 1) * n.y + inverse(2, 1) * n.z,
                    inverse(0, 2) * n.x + inverse(1, 2) * n.y + inverse(2, 2) * n.z};
      n = normalize(m).to_float();
    }
  }
  for (Vec3& p : positions) p = to_world.point(p);
  for (Vec3& axis : object_axes) axis = to_world.vector(axis);
  if (to_world.flips_handedness()) {
    for (size_t t = 0; t < triangle_count(); ++t) std::swap(indices[3 * t + 1], indices[3 * t + 2]);
  }
}

void Mesh::validate(const std::string& where) const {
  if (indices.size() % 3 != 0) {
    throw InputError(fmt::format("{}: {} triangle indices is not a multiple of 3", where, indices.size()));
  }
  for (size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= positions.size()) {
      throw InputError(fmt::format("{}: triangle {} uses vertex {} but the mesh has {} vertices", where,
                                   i / 3, indices[i], positions.size()));
    }
  }
  check_attribute(positions, positions.size(), "position", where);
  for (size_t i = 0; i < positions.size(); ++i) {
    if (!within_scene_limit(positions[i]))
      throw InputError(fmt::format("{}: position of vertex {} lies {}", where, i, beyond_scene_limit()));
  }
  check_attribute(normals, positions.size(), "normal", where);
  check_attribute(uvs, positions.size(), "uv", where);
  check_attribute(colours, positions.size(), "colour", where);
  for (size_t i = 0; i < normals.size(); ++i) {
    if (!(dot(normals[i], normals[i]) > 0.0f))
      throw InputError(fmt::format("{}: normal of vertex {} is zero", where, i));
  }
}

}  // namespace ochre
