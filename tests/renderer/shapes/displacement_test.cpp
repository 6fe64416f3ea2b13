// Displacement: a subdivided flat plane displaced by a linear ramp texture (a float EXR written here)
// rises by scale * (h - offset) at every vertex and its normals tilt to the ramp's slope; errors and
// option parsing.

#include "renderer/shapes/displacement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "renderer/image/exr_writer.h"
#include "renderer/shapes/subdivision.h"
#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::displacement_test {
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

// The control cube of tests/data/cube_quads.obj's shape, built here: 8 corners, 6 quads, with a uv atlas that
// splits vertices along its seams (each face its own uv square).
ControlMesh seamed_cube() {
  ControlMesh control;
  control.name = "cube";
  for (int k = 0; k < 8; ++k)
    control.positions.push_back({float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1)});
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    control.face_sizes.push_back(4);
    for (int c = 0; c < 4; ++c) {
      control.face_vertices.push_back(f[c]);
      control.face_uv_indices.push_back(static_cast<int>(control.uvs.size()));
      control.uvs.push_back({float(c == 1 || c == 2), float(c >= 2)});
    }
  }
  return control;
}

TEST(Displacement, ProceduralRockNeedsNoUvsKeepsSeamsClosedAndIsDeterministic) {
  const fs::path dir = test::scratch_dir();
  OiioTextureProvider textures(dir / "cache");
  DisplacementOptions options;
  options.noise = RockNoise{};
  options.noise->frequency = 3;
  options.noise->cracks = 0.5f;
  options.noise->flowstone = 0.5f;
  options.scale = 0.05f;
  Mesh mesh = subdivide(seamed_cube(), {SubdivisionScheme::CatmullClark, 3});
  const Mesh before = mesh;
  displace(mesh, options, textures);
  Mesh again = subdivide(seamed_cube(), {SubdivisionScheme::CatmullClark, 3});
  displace(again, options, textures);
  EXPECT_EQ(mesh.positions, again.positions);  // the same bits every time
  // Vertices that shared a position before (the copies along uv seams) still share it: no cracks.
  size_t seam_pairs = 0;
  float moved = 0;
  for (size_t i = 0; i < before.positions.size(); ++i) {
    moved = std::max(moved, length(mesh.positions[i] - before.positions[i]));
    for (size_t j = i + 1; j < before.positions.size(); ++j)
      if (before.positions[i] == before.positions[j]) {
        ++seam_pairs;
        EXPECT_EQ(mesh.positions[i], mesh.positions[j]) << i << " " << j;
      }
  }
  EXPECT_GT(seam_pairs, 50u);
  EXPECT_GT(moved, 0.01f);
  EXPECT_LE(moved, 0.05f * 2.0f);  // |h| <= 1 + cracks + flowstone
  // The procedural form needs no uvs.
  Mesh without_uvs = before;
  without_uvs.uvs.clear();
  displace(without_uvs, options, textures);
  EXPECT_EQ(without_uvs.positions, mesh.positions);
}

TEST(Displacement, ParsesProceduralRock) {
  const nlohmann::json good = {{"noise",
                                {{"frequency", 2},
                                 {"octaves", 6},
                                 {"seed", 4294967295u},
                                 {"cracks", 0.3},
                                 {"crack_width", 0.02},
                                 {"flowstone", 0.4},
                                 {"up", {0, 0, 2}}}},
                               {"scale", 0.2}};
  const DisplacementOptions options =
      parse_displacement(JsonFields(good, "s.json: shapes[0].displacement"), "/s");
  ASSERT_TRUE(options.noise.has_value());
  EXPECT_FLOAT_EQ(options.noise->frequency, 2.0f);
  EXPECT_EQ(options.noise->fractal.octaves, 6);
  EXPECT_EQ(options.noise->seed, 4294967295u);
  EXPECT_EQ(options.noise->up, Vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(options.scale, 0.2f);
  // Each bad form and the text its message must contain (the field, or the problem for the whole object).
  const std::string at = "s.json: shapes[0].displacement";
  const std::pair<nlohmann::json, std::string> bad[] = {
      {{{"file", "h.exr"}, {"noise", nlohmann::json::object()}}, at + ": give exactly one"},
      {{{"scale", 0.1}}, at + ": give exactly one"},
      {{{"noise", {{"frequency", 0}}}}, at + ".noise.frequency"},
      {{{"noise", {{"octaves", 17}}}}, at + ".noise.octaves"},
      {{{"noise", {{"octaves", 2.5}}}}, at + ".noise.octaves"},
      {{{"noise", {{"seed", -1}}}}, at + ".noise.seed"},
      {{{"noise", {{"seed", 4294967296.0}}}}, at + ".noise.seed"},
      {{{"noise", {{"crack_width", 1.5}}}}, at + ".noise.crack_width"},
      {{{"noise", {{"up", {0, 0, 0}}}}}, at + ".noise.up"},
      {{{"noise", {{"glitter", 1}}}}, at + ".noise.glitter: unknown parameter"},
      {{{"noise", 3}}, at + ".noise"}};
  for (const auto& [json, expected] : bad) {
    try {
      parse_displacement(JsonFields(json, at), "/s");
      FAIL() << json.dump();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace ochre::displacement_test
