#include "renderer/shapes/groove_shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "materials/core/pi.h"

namespace ochre {

namespace {

// Two counter-clockwise triangles over the quad a, b, c, d (in that order around it).
void add_quad(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
}

}  // namespace

double groove_depth(double pitch, double alpha_degrees) {
  return 0.5 * pitch / std::tan(0.5 * alpha_degrees * kDegD);
}

double groove_plate_tiles(const GroovePlate& plate) {
  if (plate.tile_pitches <= 0) return 1.0;
  return std::max(1.0, std::ceil(double(plate.length) / (double(plate.tile_pitches) * plate.pitch)));
}

Mesh make_groove_plate(const GroovePlate& plate) {
  Mesh mesh;
  mesh.name = "groove_plate";
  const double depth = groove_depth(plate.pitch, plate.alpha_degrees);
  const double width = plate.count * double(plate.pitch);
  const double y0 = -0.5 * width;
  const int tiles = static_cast<int>(groove_plate_tiles(plate));  // bounded by the caller's triangle estimate
  mesh.positions.reserve(size_t(4) * plate.count * (tiles + 1) + 1);
  // Tile boundaries along x, the same floats for both facets of every groove (shared edges stay exact).
  std::vector<float> xs(tiles + 1);
  for (int i = 0; i <= tiles; ++i) xs[i] = static_cast<float>(plate.length * (double(i) / tiles - 0.5));
  // Line j of the profile: ridges at even j, valleys at odd j.
  auto line = [&](int j) {
    return Vec2{static_cast<float>(y0 + 0.5 * j * plate.pitch),
                j % 2 == 0 ? 0.0f : static_cast<float>(-depth)};
  };
  for (int j = 0; j < 2 * plate.count; ++j) {
    const Vec2 a = line(j), b = line(j + 1);  // from a to b across y
    // Facet normal: the profile direction (dy, dz) turned by +90 degrees in the (y, z) plane (upwards).
    const double dy = b.x - a.x, dz = b.y - a.y, len = std::hypot(dy, dz);
    const Vec3 n{0.0f, static_cast<float>(-dz / len), static_cast<float>(dy / len)};
    const float va = static_cast<float>((a.x - y0) / width), vb = static_cast<float>((b.x - y0) / width);
    const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
    for (int i = 0; i <= tiles; ++i) {  // vertex pairs across the facet, tile boundary i
      const float u = static_cast<float>(double(i) / tiles);
      mesh.add_vertex({xs[i], a.x, a.y}, n, {u, va});
      mesh.add_vertex({xs[i], b.x, b.y}, n, {u, vb});
    }
    for (uint32_t i = 0; i < static_cast<uint32_t>(tiles); ++i) {
      const uint32_t k = base + 2 * i;  // a at x_i, b at x_i, a at x_i+1, b at x_i+1
      add_quad(mesh, k, k + 2, k + 3, k + 1);
    }
  }
  mesh.reserve_vertex_padding();
  return mesh;
}

namespace {

// A surface of revolution about z through the profile points (r_j, z_j), each band between successive
// points flat in the profile (its own vertices, normal perpendicular to the band) and smooth around.
Mesh revolve(const std::vector<Vec2>& profile, int segments, float height, const char* name,
             bool smooth_profile) {
  Mesh mesh;
  mesh.name = name;
  auto ring = [&](const Vec2& point, const Vec2& normal_rz, float v) {
    for (int i = 0; i <= segments; ++i) {
      const int k = i % segments;  // the seam's vertices repeat column 0's bits
      const double phi = 2.0 * std::numbers::pi * k / segments;
      const float c = static_cast<float>(std::cos(phi)), s = static_cast<float>(std::sin(phi));
      mesh.add_vertex({point.x * c, point.x * s, point.y}, {normal_rz.x * c, normal_rz.x * s, normal_rz.y},
                      {float(i) / segments, v});
    }
  };
  const uint32_t row = segments + 1;
  for (size_t j = 0; j + 1 < profile.size(); ++j) {
    const Vec2 a = profile[j], b = profile[j + 1];
    const double dr = b.x - a.x, dz = b.y - a.y, len = std::hypot(dr, dz);
    // Outward normal of the band: the profile direction (dr, dz) turned by -90 degrees.
    const Vec2 n =
        smooth_profile ? Vec2{1, 0} : Vec2{static_cast<float>(dz / len), static_cast<float>(-dr / len)};
    const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
    ring(a, n, a.y / height);
    ring(b, n, b.y / height);
    for (uint32_t i = 0; i < static_cast<uint32_t>(segments); ++i)
      add_quad(mesh, base + i, base + i + 1, base + row + i + 1, base + row + i);
  }
  mesh.reserve_vertex_padding();
  return mesh;
}

}  // namespace

Mesh make_cylinder(float radius, float height, int segments) {
  return revolve({{radius, 0.0f}, {radius, height}}, segments, height, "cylinder", true);
}

double groove_plate_triangle_count(const GroovePlate& plate) {
  return 4.0 * plate.count * groove_plate_tiles(plate);
}

double cylinder_triangle_count(int segments) {
  return 2.0 * segments;
}

double groove_count(const GroovedCylinder& c) {
  return std::max(1.0, std::floor(double(c.height) / c.pitch));
}

double grooved_cylinder_triangle_count(const GroovedCylinder& c) {
  return 4.0 * groove_count(c) * c.segments;
}

Mesh make_grooved_cylinder(const GroovedCylinder& c) {
  const int grooves = static_cast<int>(groove_count(c));  // bounded by the caller's triangle estimate
  const double depth = groove_depth(c.pitch, c.alpha_degrees);
  std::vector<Vec2> profile;
  for (int j = 0; j <= 2 * grooves; ++j)
    profile.push_back({static_cast<float>(j % 2 == 0 ? c.radius : c.radius - depth),
                       static_cast<float>(0.5 * j * c.pitch)});
  return revolve(profile, c.segments, static_cast<float>(grooves * double(c.pitch)), "grooved_cylinder",
                 false);
}

}  // namespace ochre
