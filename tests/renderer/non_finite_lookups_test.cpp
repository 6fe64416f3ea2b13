// The renderer's lookups given NaN, +-inf and huge coordinates (docs/nodes.md, "Non-finite values"):
// texture lookups (resident MIP levels and OIIO's TextureSystem; MipPyramid itself in
// mip_pyramid_test.cpp) and the environment map's cells
// give finite results from indices inside their tables, and huge periodic coordinates read the same texel
// as 0. Meshes and environment maps holding NaN or infinities are rejected at load, naming what is wrong.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "renderer/geometry/mesh.h"
#include "renderer/image/exr_writer.h"
#include "renderer/lights/environment_map.h"
#include "renderer/sampling/distribution_2d.h"
#include "renderer/texture/texture_system.h"
#include "spectra/input_error.h"
#include "support/awkward_floats.h"
#include "support/test_paths.h"

namespace ochre::test::non_finite_lookups_test {
namespace {

using test::awkward_floats;

std::vector<float> awkward_values() {  // and ordinary ones
  std::vector<float> v = awkward_floats();
  v.insert(v.end(), {0.3f});
  return v;
}

// Every texel 0.5 (a 4x4 linear EXR): whatever the coordinates, a lookup reads 0.5 or, for NaN and infinite
// coordinates, 0.
void expect_texture_lookups_finite(std::size_t resident_budget) {
  const auto dir = test::scratch_dir();
  ExrImage image;
  image.width = image.height = 4;
  for (const char* name : {"B", "G", "R"}) image.channels.emplace_back(name, std::vector<float>(16, 0.5f));
  write_exr(dir / "grey.exr", image);
  OiioTextureProvider textures(dir / "cache", resident_budget);
  int channels = 0;
  const int id = textures.add_texture(dir / "grey.exr", "linear", channels);
  ASSERT_EQ(textures.resident_count(), resident_budget > 0 ? 1 : 0);
  for (float u : awkward_values())
    for (float v : awkward_values())
      for (float footprint : {kNaN, kInf, 1e30f, 0.0f, 0.3f}) {
        std::array<float, 3> out{-1.0f, -1.0f, -1.0f};
        textures.lookup(id, Vec2{u, v}, footprint, 0, 3, out.data());
        const bool readable = std::isfinite(u) && std::isfinite(v);
        for (float x : out)
          EXPECT_NEAR(x, readable ? 0.5f : 0.0f, 1e-6f) << u << ", " << v << ", " << footprint;
      }
}

TEST(NonFiniteLookups, ResidentTextureAnyCoordinateAndFootprint) {
  expect_texture_lookups_finite(OiioTextureProvider::kDefaultResidentBudget);
}

TEST(NonFiniteLookups, TextureSystemAnyCoordinateAndFootprint) {
  expect_texture_lookups_finite(0);
}

TEST(NonFiniteLookups, DistributionCellsStayInTheGrid) {
  const Distribution2D d(std::vector<double>(6 * 3, 1.0), 6, 3);
  for (float x : awkward_values()) {
    EXPECT_TRUE(d.column_of(x) >= 0 && d.column_of(x) < 6) << x;
    EXPECT_TRUE(d.row_of(x) >= 0 && d.row_of(x) < 3) << x;
  }
  EXPECT_EQ(d.column_of(kNaN), 0);
  EXPECT_EQ(d.column_of(kInf), 5);
  EXPECT_EQ(d.row_of(-kInf), 0);
}

TEST(NonFiniteLookups, EnvironmentMapNonFiniteDirections) {
  const EnvironmentMap map(8, 4, std::vector<RGB>(32, RGB{1.0f, 0.5f, 0.25f}));
  const Vec2 uv = direction_to_equirect_uv({kNaN, kNaN, kNaN});
  EXPECT_EQ(uv.x, 0.0f);
  EXPECT_EQ(uv.y, 0.0f);
  for (float x : awkward_values()) {
    for (const Vec3& d : {Vec3{x, 0.5f, 0.25f}, Vec3{0.5f, x, 0.25f}, Vec3{x, x, x}}) {
      EXPECT_LT(map.texel_index(d), 32u) << x;
      EXPECT_LT(map.texel_key(d), map.texel_key_count()) << x;
      EXPECT_TRUE(std::isfinite(map.lookup(d).r)) << x;
    }
  }
}

TEST(NonFiniteLookups, EnvironmentMapRejectsNonFiniteTexels) {
  for (float bad : {kNaN, kInf, -kInf}) {
    std::vector<RGB> texels(32, RGB{1.0f, 1.0f, 1.0f});
    texels[8 + 3].b = bad;  // column 3, row 1
    try {
      const EnvironmentMap map(8, 4, texels);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("texel (column 3, row 1) is not finite"), std::string::npos)
          << e.what();
    }
  }
}

Mesh triangle() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  return m;
}

void expect_mesh_rejected(const Mesh& m, const std::string& expected) {
  try {
    m.validate("scan.ply");
    ADD_FAILURE() << "accepted, expected " << expected;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scan.ply: " + expected), std::string::npos) << e.what();
  }
}

TEST(NonFiniteLookups, MeshesRejectNonFiniteAttributes) {
  for (float bad : {kNaN, kInf, -kInf}) {
    Mesh colours = triangle();
    colours.colours = {{1, 1, 1}, {1, bad, 1}, {1, 1, 1}};
    expect_mesh_rejected(colours, "colour of vertex 1 is not finite");
    Mesh uvs = triangle();
    uvs.uvs = {{0, 0}, {0, 0}, {bad, 0}};
    expect_mesh_rejected(uvs, "uv of vertex 2 is not finite");
    Mesh normals = triangle();
    normals.normals = {{0, 0, bad}, {0, 0, 1}, {0, 0, 1}};
    expect_mesh_rejected(normals, "normal of vertex 0 is not finite");
  }
  Mesh huge_uvs = triangle();  // finite, however large: accepted (lookups wrap them)
  huge_uvs.uvs = {{1e30f, -kLargest}, {kLargest, 0}, {0, 3e38f}};
  EXPECT_NO_THROW(huge_uvs.validate("scan.ply"));
}

}  // namespace
}  // namespace ochre::test::non_finite_lookups_test
