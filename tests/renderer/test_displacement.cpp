// Displacement: a subdivided flat plane displaced by a linear ramp texture (a float EXR written here)
// rises by scale * (h - offset) at every vertex and its normals tilt to the ramp's slope; errors and
// option parsing.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "renderer/displacement.h"
#include "renderer/exr_writer.h"
#include "renderer/input_error.h"
#include "renderer/subdivision.h"
#include "support/test_paths.h"

namespace ochre {
namespace {

namespace fs = std::filesystem;

constexpr int kRampWidth = 64;

// One-channel float EXR whose texel centres hold h = u: texel i has value (i + 0.5) / width, so
// bilinear filtering reproduces h(u) = u exactly between the first and last texel centres.
fs::path write_ramp(const fs::path& dir) {
  ExrImage image;
  image.width = kRampWidth;
  image.height = 4;
  std::vector<float> values;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) values.push_back((float(x) + 0.5f) / float(kRampWidth));
  image.channels.emplace_back("Y", std::move(values));
  const fs::path path = dir / "ramp.exr";
  write_exr(path, image);
  return path;
}

// A 2 x 2 quad plane on [0, 1]^2 (z = 0, normal +z) with uv = (x, y), subdivided 3 times.
Mesh flat_plane() {
  ControlMesh control;
  control.name = "plane";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) {
      control.positions.push_back({float(i) / 2, float(j) / 2, 0});
      control.uvs.push_back({float(i) / 2, float(j) / 2});
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = 3 * j + i;
      control.face_sizes.push_back(4);
      control.face_vertices.insert(control.face_vertices.end(), {a, a + 1, a + 4, a + 3});
    }
  control.face_uv_indices = control.face_vertices;
  return subdivide(control, {SubdivisionScheme::CatmullClark, 3});
}

TEST(Displacement, LinearRampRaisesVerticesAndTiltsNormals) {
  const fs::path dir = test::scratch_dir();
  OiioTextureProvider textures(dir / "cache");
  Mesh mesh = flat_plane();
  const Mesh before = mesh;
  const DisplacementOptions options{write_ramp(dir), "linear", 0.5f, 0.25f};
  displace(mesh, options, textures);
  // Expected surface: z = 0.5 (x - 0.25), normal along (-0.5, 0, 1).
  const Vec3 expected_normal = normalize(Vec3{-0.5f, 0, 1});
  const float edge = 0.5f / kRampWidth, spacing = 1.0f / 16;  // texel centre margin, vertex spacing
  int checked_heights = 0, checked_normals = 0;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const float u = before.uvs[i].x;
    EXPECT_FLOAT_EQ(mesh.positions[i].x, before.positions[i].x);
    EXPECT_FLOAT_EQ(mesh.positions[i].y, before.positions[i].y);
    if (u < edge || u > 1 - edge) continue;  // the periodic wrap blends the last and first texels
    EXPECT_NEAR(mesh.positions[i].z, 0.5f * (u - 0.25f), 1e-5f) << "u = " << u;
    ++checked_heights;
    if (u < spacing + edge || u > 1 - spacing - edge) continue;  // a neighbour on the wrapped column
    EXPECT_GT(dot(mesh.normals[i], expected_normal), 1 - 1e-5f) << "u = " << u;
    ++checked_normals;
  }
  EXPECT_EQ(checked_heights, 15 * 17);
  EXPECT_EQ(checked_normals, 13 * 17);
}

TEST(Displacement, NeedsUvsAndAReadableTexture) {
  const fs::path dir = test::scratch_dir();
  OiioTextureProvider textures(dir / "cache");
  Mesh mesh = flat_plane();
  Mesh without_uvs = mesh;
  without_uvs.uvs.clear();
  EXPECT_THROW(displace(without_uvs, {write_ramp(dir)}, textures), InputError);
  try {
    displace(mesh, {dir / "missing.exr"}, textures);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
  }
}

TEST(Displacement, ParsesOptions) {
  const nlohmann::json good = {{"file", "h.exr"}, {"scale", 0.1}, {"offset", 0.5}, {"colorspace", "auto"}};
  const DisplacementOptions options =
      parse_displacement(JsonFields(good, "s.json: shapes[0].displacement"), "/scenes");
  EXPECT_EQ(options.file, fs::path("/scenes/h.exr"));
  EXPECT_FLOAT_EQ(options.scale, 0.1f);
  EXPECT_FLOAT_EQ(options.offset, 0.5f);
  EXPECT_EQ(options.colorspace, "auto");
  for (const nlohmann::json& bad :
       {nlohmann::json{{"scale", 1}}, nlohmann::json{{"file", "h.exr"}, {"colorspace", "p3"}},
        nlohmann::json{{"file", "h.exr"}, {"sclae", 1}}}) {
    try {
      parse_displacement(JsonFields(bad, "s.json: shapes[0].displacement"), "/scenes");
      FAIL() << bad.dump();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("s.json: shapes[0].displacement"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace ochre
