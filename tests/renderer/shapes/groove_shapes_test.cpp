// Explicit groove plates (renderer/shapes/groove_shapes.h): tiling the facets along the grooves changes the
// triangles, not the surface.
#include "renderer/shapes/groove_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

namespace ochre::groove_shapes_test {
namespace {

double area(const Mesh& mesh) {
  double sum = 0;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
               c = mesh.positions[mesh.indices[3 * t + 2]];
    const Vec3 n = cross(b - a, c - a);
    sum += 0.5 * std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
  }
  return sum;
}

TEST(GroovePlate, TilesCoverTheSameFacetsAsOneStrip) {
  GroovePlate strip{45, 0.25f, 6, 20, 0};
  GroovePlate tiled = strip;
  tiled.tile_pitches = 8;  // 20 / 2 = 10 tiles
  const Mesh a = make_groove_plate(strip), b = make_groove_plate(tiled);
  EXPECT_EQ(a.triangle_count(), 4u * 6);
  EXPECT_EQ(b.triangle_count(), 4u * 6 * 10);
  // Facet width: half the pitch over sin(alpha / 2); area = 2 facets x count x width x length.
  const double facet = 0.5 * 0.25 / std::sin(22.5 * std::acos(-1.0) / 180);
  EXPECT_NEAR(area(a), 2 * 6 * facet * 20, 1e-4);
  EXPECT_NEAR(area(b), area(a), 1e-4);
}

// Every normal is the facet's (up and across the grooves), every u runs 0..1 along the plate as x does.
TEST(GroovePlate, TiledFacetsKeepTheirNormalsAndUv) {
  const Mesh mesh = make_groove_plate({90, 1, 3, 40, 8});
  ASSERT_EQ(mesh.positions.size(), mesh.uvs.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_FLOAT_EQ(mesh.uvs[i].x, mesh.positions[i].x / 40 + 0.5f);
    EXPECT_EQ(mesh.normals[i].x, 0.0f);
    EXPECT_NEAR(std::abs(mesh.normals[i].y), std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(mesh.normals[i].z, std::sqrt(0.5), 1e-6);
  }
}

// Tile boundaries are the same floats on both facets of a groove and on neighbouring grooves, so shared
// edges stay watertight: each (x, y, z) of the plate's ridge and valley lines appears at every tile
// boundary.
TEST(GroovePlate, TileBoundariesAreSharedExactly) {
  const Mesh mesh = make_groove_plate({60, 0.5f, 4, 10, 8});  // 10 / 4: 3 tiles
  std::set<float> xs;
  for (const Vec3& p : mesh.positions) xs.insert(p.x);
  EXPECT_EQ(xs.size(), 4u);
  std::set<std::tuple<float, float, float>> points;
  for (const Vec3& p : mesh.positions) points.insert({p.x, p.y, p.z});
  EXPECT_EQ(points.size(), 4u * (2 * 4 + 1));  // 4 boundaries x (ridges + valleys)
}

}  // namespace
}  // namespace ochre::groove_shapes_test
