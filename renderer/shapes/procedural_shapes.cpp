#include "renderer/shapes/procedural_shapes.h"

#include <fmt/format.h>

#include <cmath>

#include "renderer/util/memory_budget.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

void require_positive(float value, const char* shape, const char* parameter) {
  if (!(value > 0.0f) || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: {} must be a positive finite number, got {}", shape, parameter, value));
  }
}

void require_at_least(int value, int minimum, const char* shape, const char* parameter) {
  if (value < minimum)
    throw InputError(fmt::format("{}: {} must be at least {}, got {}", shape, parameter, minimum, value));
}

}  // namespace

Mesh make_plane(Vec2 size) {
  require_positive(size.x, "plane", "size.x");
  require_positive(size.y, "plane", "size.y");
  Mesh mesh;
  mesh.name = "plane";
  const float hx = 0.5f * size.x, hy = 0.5f * size.y;
  const Vec3 n{0, 0, 1};
  mesh.add_vertex({-hx, -hy, 0}, n, {0, 0});
  mesh.add_vertex({hx, -hy, 0}, n, {1, 0});
  mesh.add_vertex({hx, hy, 0}, n, {1, 1});
  mesh.add_vertex({-hx, hy, 0}, n, {0, 1});
  mesh.add_triangle(0, 1, 2);
  mesh.add_triangle(0, 2, 3);
  mesh.reserve_vertex_padding();
  return mesh;
}

Mesh make_disk(float radius, int segments) {
  require_positive(radius, "disk", "radius");
  require_at_least(segments, 3, "disk", "segments");
  Mesh mesh;
  mesh.name = "disk";
  mesh.positions.reserve(segments + 2);
  const Vec3 n{0, 0, 1};
  mesh.add_vertex({0, 0, 0}, n, {0.5f, 0.5f});
  for (int i = 0; i < segments; ++i) {
    const double phi = 2.0 * M_PI * i / segments;
    const float c = static_cast<float>(std::cos(phi)), s = static_cast<float>(std::sin(phi));
    mesh.add_vertex({radius * c, radius * s, 0}, n, {0.5f * (c + 1), 0.5f * (s + 1)});
  }
  for (int i = 0; i < segments; ++i) {
    mesh.add_triangle(0, 1 + i, 1 + (i + 1) % segments);
  }
  return mesh;
}

Mesh make_cube(Vec3 size) {
  require_positive(size.x, "cube", "size.x");
  require_positive(size.y, "cube", "size.y");
  require_positive(size.z, "cube", "size.z");
  // Mitsuba 3's cube (src/shapes/cube.cpp): four corners per face, each face two triangles (a, b, c) and
  // (d, a, c) over its corners a, b, c, d, whose Mitsuba uvs are (0,1), (1,1), (1,0), (0,0).
  static constexpr float kCorners[6][4][3] = {{{1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, {-1, -1, -1}},
                                              {{1, 1, -1}, {-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}},
                                              {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
                                              {{1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}},
                                              {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
                                              {{1, 1, -1}, {1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}}};
  static constexpr float kNormals[6][3] = {{0, -1, 0}, {0, 1, 0},  {1, 0, 0},
                                           {0, 0, 1},  {-1, 0, 0}, {0, 0, -1}};
  static constexpr Vec2 kUv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // 1 - v of Mitsuba's
  Mesh mesh;
  mesh.name = "cube";
  const Vec3 half = size * 0.5f;
  for (int face = 0; face < 6; ++face) {
    const Vec3 n{kNormals[face][0], kNormals[face][1], kNormals[face][2]};
    for (int corner = 0; corner < 4; ++corner) {
      const float* c = kCorners[face][corner];
      mesh.add_vertex({c[0] * half.x, c[1] * half.y, c[2] * half.z}, n, kUv[corner]);
    }
    const auto base = static_cast<uint32_t>(4 * face);
    mesh.add_triangle(base, base + 1, base + 2);
    mesh.add_triangle(base + 3, base, base + 2);
  }
  mesh.reserve_vertex_padding();
  return mesh;
}

void flip_normals(Mesh& mesh) {
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  for (Vec3& n : mesh.normals) n = -n;
}

void flip_uv_v(Mesh& mesh) {
  for (Vec2& uv : mesh.uvs) uv.y = 1.0f - uv.y;
}

double sphere_triangle_count(int subdivisions) {
  const double s = subdivisions;
  return 4.0 * s * s - 4.0 * s;  // 2 per grid cell, but one at each pole
}

double sphere_memory_bytes(int subdivisions) {
  return sphere_triangle_count(subdivisions) * kTessellatedTriangleBytes;
}

// Vertex grid (subdivisions + 1) rows x (2 subdivisions + 1) columns; row 0 is the south pole.
// Positions of the last column and of each pole row are computed from the same (row, column % n)
// inputs as their twins, so duplicates are bit-identical.
Mesh make_sphere(float radius, int subdivisions) {
  require_positive(radius, "sphere", "radius");
  require_at_least(subdivisions, 2, "sphere", "subdivisions");
  const int rows = subdivisions, columns = 2 * subdivisions;
  Mesh mesh;
  mesh.name = "sphere";
  mesh.positions.reserve(size_t(rows + 1) * (columns + 1) + 1);
  for (int row = 0; row <= rows; ++row) {
    const double theta = M_PI * row / rows;  // from the south pole
    const double z = row == 0 ? -1.0 : (row == rows ? 1.0 : -std::cos(theta));
    const double ring = (row == 0 || row == rows) ? 0.0 : std::sin(theta);
    for (int column = 0; column <= columns; ++column) {
      const double phi = 2.0 * M_PI * (column % columns) / columns;
      const Vec3 n{static_cast<float>(ring * std::cos(phi)), static_cast<float>(ring * std::sin(phi)),
                   static_cast<float>(z)};
      const Vec2 uv{static_cast<float>(column) / columns, static_cast<float>(row) / rows};
      mesh.add_vertex(n * radius, normalize(n), uv);
    }
  }
  auto vertex = [&](int row, int column) { return static_cast<uint32_t>(row * (columns + 1) + column); };
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const uint32_t a = vertex(row, column), b = vertex(row, column + 1);
      const uint32_t c = vertex(row + 1, column + 1), d = vertex(row + 1, column);
      // Counter-clockwise seen from outside: u grows eastwards (+phi), v grows northwards (+z).
      if (row != 0) mesh.add_triangle(a, b, c);         // skip the degenerate triangle at the south pole
      if (row != rows - 1) mesh.add_triangle(a, c, d);  // and at the north pole
    }
  }
  return mesh;
}

Mesh make_cone(float radius, float top_radius, float height, int segments) {
  require_positive(radius, "cone", "radius");
  require_positive(height, "cone", "height");
  if (!(top_radius >= 0.0f) || !std::isfinite(top_radius))
    throw InputError(fmt::format("cone: top_radius must be a finite number >= 0, got {}", top_radius));
  require_at_least(segments, 3, "cone", "segments");
  Mesh mesh;
  mesh.name = "cone";
  // The slant's outward normal in the (r, z) plane: the profile direction (top - radius, height) turned by
  // -90 degrees.
  const double dr = double(top_radius) - radius, len = std::hypot(dr, double(height));
  const double nr = height / len, nz = -dr / len;
  const uint32_t row = static_cast<uint32_t>(segments) + 1;
  mesh.positions.reserve(2 * size_t(row) + 1);
  for (const float z : {0.0f, height}) {
    const float r = z == 0.0f ? radius : top_radius;
    for (int i = 0; i <= segments; ++i) {
      const double phi = 2.0 * M_PI * (i % segments) / segments;  // the seam repeats column 0's bits
      const double c = std::cos(phi), s = std::sin(phi);
      mesh.add_vertex({static_cast<float>(r * c), static_cast<float>(r * s), z},
                      {static_cast<float>(nr * c), static_cast<float>(nr * s), static_cast<float>(nz)},
                      {float(i) / segments, z / height});
    }
  }
  for (uint32_t i = 0; i < static_cast<uint32_t>(segments); ++i) {
    mesh.add_triangle(i, i + 1, row + i + 1);
    if (top_radius > 0.0f) mesh.add_triangle(i, row + i + 1, row + i);  // a pointed cone has no top edge
  }
  mesh.reserve_vertex_padding();
  return mesh;
}

double cone_triangle_count(int segments, bool pointed) {
  return (pointed ? 1.0 : 2.0) * segments;
}

}  // namespace ochre
