#include "renderer/shapes/mesh_import.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::mesh_import_test {
namespace {

std::filesystem::path data(const char* name) {
  return test::source_dir() / "tests" / "data" / name;
}

Vec3 face_normal(const Mesh& m, size_t t) {
  const Vec3 &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
             &c = m.positions[m.indices[3 * t + 2]];
  return cross(b - a, c - a);
}

// Index of the vertex at position p (exact match), or -1.
int find_vertex(const Mesh& m, Vec3 p) {
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (m.positions[i] == p) return static_cast<int>(i);
  return -1;
}

TEST(MeshImport, ObjQuadWithUvsAndNormals) {
  const Mesh m = import_mesh(data("quad.obj"), Transform::identity());
  EXPECT_EQ(m.name, "quad");
  EXPECT_EQ(m.triangle_count(), 2u);
  EXPECT_EQ(m.vertex_count(), 4u);  // identical vertices joined
  ASSERT_EQ(m.uvs.size(), 4u);
  ASSERT_EQ(m.normals.size(), 4u);
  EXPECT_TRUE(m.colours.empty());
  const int top_right = find_vertex(m, {1, 0.5f, 0});
  ASSERT_GE(top_right, 0);
  EXPECT_FLOAT_EQ(m.uvs[top_right].x, 1.0f);
  EXPECT_FLOAT_EQ(m.uvs[top_right].y, 1.0f);
  EXPECT_NEAR(m.surface_area(), 2.0f, 1e-6f);
  for (size_t t = 0; t < 2; ++t) EXPECT_GT(face_normal(m, t).z, 0.0f);  // winding kept
  EXPECT_EQ(m.normals[0], Vec3(0, 0, 1));
}

TEST(MeshImport, AppliesToWorldAndFlipsWindingForMirrors) {
  const Mesh moved =
      import_mesh(data("quad.obj"), Transform::translate({0, 0, 3}) * Transform::scale({2, 2, 2}));
  EXPECT_GE(find_vertex(moved, {2, 1, 3}), 0);
  EXPECT_NEAR(moved.surface_area(), 8.0f, 1e-5f);
  const Mesh mirrored = import_mesh(data("quad.obj"), Transform::scale({1, 1, -1}));
  for (size_t t = 0; t < 2; ++t) {
    EXPECT_LT(face_normal(mirrored, t).z, 0.0f);
    EXPECT_GT(dot(face_normal(mirrored, t), mirrored.normals[mirrored.indices[3 * t]]), 0.0f);
  }
}

TEST(MeshImport, FlipUvV) {
  MeshImportOptions options;
  options.flip_uv_v = true;
  const Mesh m = import_mesh(data("quad.obj"), Transform::identity(), options);
  const int top_right = find_vertex(m, {1, 0.5f, 0});
  ASSERT_GE(top_right, 0);
  EXPECT_FLOAT_EQ(m.uvs[top_right].y, 0.0f);
}

TEST(MeshImport, NormalsAreGeneratedOnlyOnRequest) {
  const Mesh flat = import_mesh(data("tetrahedron.obj"), Transform::identity());
  EXPECT_EQ(flat.triangle_count(), 4u);
  EXPECT_TRUE(flat.normals.empty());
  EXPECT_TRUE(flat.uvs.empty());
  MeshImportOptions options;
  options.smooth_normals = true;
  const Mesh smooth = import_mesh(data("tetrahedron.obj"), Transform::identity(), options);
  ASSERT_EQ(smooth.normals.size(), smooth.positions.size());
  for (size_t i = 0; i < smooth.positions.size(); ++i) {
    EXPECT_NEAR(length(smooth.normals[i]), 1.0f, 1e-5f);
    // Smooth normals of a tetrahedron centred at the origin point away from the centre.
    EXPECT_GT(dot(smooth.normals[i], smooth.positions[i]), 0.9f * length(smooth.positions[i]));
  }
}

TEST(MeshImport, PlyEightBitColoursAreDecodedFromSrgb) {
  EXPECT_EQ(vertex_colour_encoding(data("colours.ply")), VertexColourEncoding::Srgb);
  const Mesh m = import_mesh(data("colours.ply"), Transform::identity());
  EXPECT_EQ(m.triangle_count(), 2u);
  EXPECT_EQ(m.vertex_count(), 4u);
  ASSERT_EQ(m.colours.size(), 4u);
  const auto colour_at = [&](Vec3 p) {
    const int i = find_vertex(m, p);
    EXPECT_GE(i, 0);
    return i >= 0 ? m.colours[i] : Vec3{-1, -1, -1};
  };
  // IEC 61966-2-1: 128/255 -> ((0.50196 + 0.055)/1.055)^2.4 = 0.215861; 10/255 -> 0.039216/12.92.
  EXPECT_NEAR(colour_at({0, 0, 0}).x, 1.0f, 1e-6f);
  EXPECT_EQ(colour_at({0, 0, 0}).y, 0.0f);
  EXPECT_NEAR(colour_at({1, 0, 0}).x, 0.2158605f, 2e-6f);
  EXPECT_NEAR(colour_at({1, 0, 0}).z, 0.2158605f, 2e-6f);
  EXPECT_NEAR(colour_at({1, 1, 0}).y, 0.0030353f, 1e-6f);
  EXPECT_NEAR(colour_at({1, 1, 0}).z, 1.0f, 1e-6f);
  EXPECT_EQ(colour_at({0, 1, 0}), Vec3(0, 0, 0));
  EXPECT_TRUE(m.normals.empty());
}

TEST(MeshImport, PlyFloatColoursAreLinear) {
  EXPECT_EQ(vertex_colour_encoding(data("float_colours.ply")), VertexColourEncoding::Linear);
  const Mesh m = import_mesh(data("float_colours.ply"), Transform::identity());
  ASSERT_EQ(m.colours.size(), m.positions.size());
  for (const Vec3& c : m.colours) EXPECT_EQ(c, Vec3(0.5f, 0.25f, 0.125f));
}

TEST(MeshImport, GltfNodesAreInstancedAndMerged) {
  const Mesh m = import_mesh(data("two_triangles.gltf"), Transform::identity());
  EXPECT_EQ(m.triangle_count(), 2u);  // one mesh used by two nodes
  EXPECT_EQ(m.vertex_count(), 6u);
  // Node transforms: root translation (0, 0, 5), second child (10, 0, 0) more.
  EXPECT_GE(find_vertex(m, {1, 0, 5}), 0);
  EXPECT_GE(find_vertex(m, {11, 0, 5}), 0);
  ASSERT_EQ(m.normals.size(), 6u);
  ASSERT_EQ(m.uvs.size(), 6u);
  // glTF stores uv (1, 0.25) for vertex (1, 0, 0) with the origin at the image's top left;
  // ours is at the bottom left, so v = 0.75.
  const int i = find_vertex(m, {11, 0, 5});
  EXPECT_FLOAT_EQ(m.uvs[i].x, 1.0f);
  EXPECT_FLOAT_EQ(m.uvs[i].y, 0.75f);
  EXPECT_EQ(m.normals[i], Vec3(0, 0, 1));
  EXPECT_TRUE(m.colours.empty());
}

TEST(MeshImport, MissingFileNamesThePath) {
  const auto missing = data("does_not_exist.obj");
  try {
    import_mesh(missing, Transform::identity());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}

TEST(MeshImport, FileWithoutTrianglesIsAnError) {
  try {
    import_mesh(data("no_triangles.obj"), Transform::identity());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_triangles.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contains no triangles"), std::string::npos) << e.what();
  }
}

TEST(MeshImport, GarbageFileIsAnError) {
  const auto file = test::scratch_dir() / "garbage.ply";
  std::FILE* f = std::fopen(file.c_str(), "wb");
  std::fputs("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n", f);
  std::fclose(f);
  EXPECT_THROW(import_mesh(file, Transform::identity()), InputError);
}

TEST(MeshImport, SharedScans) {
  OCHRE_REQUIRE_SHARED();
  const auto start = std::chrono::steady_clock::now();
  const Mesh bunny =
      import_mesh(test::shared_dir() / "assets/meshes/stanford-bunny.obj", Transform::identity());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ info ] stanford-bunny.obj: %zu triangles, %zu vertices, imported in %.3f s\n",
              bunny.triangle_count(), bunny.vertex_count(), seconds);
  EXPECT_GT(bunny.triangle_count(), 60000u);
  EXPECT_LT(bunny.vertex_count(), bunny.triangle_count());  // vertices joined

  const Mesh gargo = import_mesh(test::shared_dir() / "assets/meshes/3dhop/gargo.ply", Transform::identity());
  EXPECT_EQ(gargo.triangle_count(), 50000u);
  ASSERT_EQ(gargo.colours.size(), gargo.positions.size());
  ASSERT_EQ(gargo.normals.size(), gargo.positions.size());
  Vec3 mean{0, 0, 0};
  for (const Vec3& c : gargo.colours) {
    ASSERT_GE(std::min({c.x, c.y, c.z}), 0.0f);
    ASSERT_LE(std::max({c.x, c.y, c.z}), 1.0f);
    mean += c / static_cast<float>(gargo.colours.size());
  }
  std::printf("[ info ] gargo.ply: %zu triangles, mean linear vertex colour (%.4f, %.4f, %.4f)\n",
              gargo.triangle_count(), mean.x, mean.y, mean.z);
}

}  // namespace
}  // namespace ochre::mesh_import_test
