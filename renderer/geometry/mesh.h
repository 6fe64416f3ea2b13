#pragma once
// Mesh: an indexed triangle mesh with optional per-vertex normals, UVs and colours.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "materials/core/vec3.h"
#include "renderer/geometry/transform.h"

namespace ochre {

struct Mesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<uint32_t> indices;  // 3 per triangle, counter-clockwise seen from the front
  std::vector<Vec3> normals;      // per vertex; empty = flat shading
  std::vector<Vec2> uvs;          // per vertex; empty = none (v = 0 is the bottom row of an image)
  std::vector<Vec3> colours;      // per vertex, linear Rec.709 RGB; empty = none
  int material = -1;              // index into the scene's materials
  // Images of the object's x, y, z axes under the transforms applied so far (the linear part of the
  // object-to-world transform): what object-space directions in materials refer to.
  std::array<Vec3, 3> object_axes{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};

  size_t triangle_count() const { return indices.size() / 3; }
  // Builders of generated meshes (procedural shapes, groove plates): a vertex with normal and uv, a
  // counter-clockwise triangle of vertex indices.
  void add_vertex(const Vec3& p, const Vec3& n, const Vec2& uv) {
    positions.push_back(p);
    normals.push_back(n);
    uvs.push_back(uv);
  }
  void add_triangle(uint32_t a, uint32_t b, uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
  size_t vertex_count() const { return positions.size(); }
  float triangle_area(size_t triangle) const;
  // Sum of the triangle areas.
  float surface_area() const;
  // Axis-aligned box of the positions (lo = +inf, hi = -inf when there are none).
  struct Bounds {
    Vec3 lo{INFINITY, INFINITY, INFINITY};
    Vec3 hi{-INFINITY, -INFINITY, -INFINITY};
    void include(const Bounds& other) {
      lo = min(lo, other.lo);
      hi = max(hi, other.hi);
    }
  };
  Bounds bounds() const;

  // Applies `to_world` to positions and (by the inverse transpose, renormalized) to normals.
  // When the transform flips handedness the winding is reversed so the geometric normal keeps
  // agreeing with the transformed shading normals.
  void transform(const Transform& to_world);

  // Throws InputError starting with `where` when: the index count is not a multiple of 3, an
  // index is out of range, a position/normal/UV/colour is not finite, a normal has zero
  // length, or normals/uvs/colours are non-empty with a size different from positions.
  void validate(const std::string& where) const;

  // Reserves one spare position so that Accel can share the array with Embree without a copy
  // (Embree reads 16 bytes per vertex). Copying a Mesh drops the spare capacity; moving keeps it.
  void reserve_vertex_padding() { positions.reserve(positions.size() + 1); }
};

}  // namespace ochre
