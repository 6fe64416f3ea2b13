// `ochre export-mesh` (docs/cli.md, "ochre export-mesh"): the PLY file holds the surface the renderer
// renders, in world coordinates, and a scene that uses the file instead of the shape renders the same image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::export_mesh_test {
namespace {

namespace fs = std::filesystem;

// A sphere (at x = 1000 unless `x` says otherwise; the camera beside it) and a floor: two meshes.
std::string scene(const std::string& ball, const std::string& x = "1000") {
  return R"({"camera": {"type": "perspective", "fov": 40, "eye": [)" + x + R"(, 2, 8], "target": [)" + x +
         R"(, 2, 3]},
  "film": {"resolution": [24, 16]}, "integrator": {"spp": 4, "max_depth": 3},
  "materials": {"grey": {"type": "lambert", "color": 0.5}},
  "lights": [{"type": "point", "position": [)" +
         x + R"(, 6, 8], "intensity": 40}, {"type": "environment", "radiance": 0.2}],
  "shapes": [)" +
         ball + R"(, {"type": "plane", "name": "floor", "size": [40, 40], "material": "grey",
             "transform": [{"translate": [)" +
         x + R"(, 0, 3]}]}]})";
}

std::string sphere(const std::string& x = "1000") {
  return R"({"type": "sphere", "name": "ball", "radius": 1.5, "material": "grey", "transform": [{"translate": [)" +
         x + R"(, 2, 3]}]})";
}

struct Ply {
  std::string header;
  std::vector<float> vertices;  // x y z nx ny nz s t per vertex
  size_t vertex_count = 0, face_count = 0;
};

Ply read_ply(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  Ply ply;
  for (std::string line; std::getline(in, line);) {
    ply.header += line + "\n";
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == "element" && second == "vertex") words >> ply.vertex_count;
    if (first == "element" && second == "face") words >> ply.face_count;
    if (line == "end_header") break;
  }
  ply.vertices.resize(ply.vertex_count * 8);
  in.read(reinterpret_cast<char*>(ply.vertices.data()), std::streamsize(ply.vertices.size() * sizeof(float)));
  return ply;
}

TEST(ExportMesh, TheSphereAsRenderedInWorldCoordinatesWithItsNormals) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", scene(sphere()));
  const CommandResult r = run_ochre("export-mesh scene.json --shape ball -o ball.ply", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("mesh 'ball'"), std::string::npos) << r.output;
  const Ply ply = read_ply(dir / "ball.ply");
  EXPECT_NE(ply.header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(ply.header.find("property float nx"), std::string::npos);
  EXPECT_NE(ply.header.find("property float s"), std::string::npos);
  ASSERT_GT(ply.vertex_count, 100u);
  EXPECT_GT(ply.face_count, 100u);
  double worst_radius = 0, worst_normal = 0;
  for (size_t i = 0; i < ply.vertex_count; ++i) {
    const float* v = &ply.vertices[8 * i];
    const double d[3] = {v[0] - 1000.0, v[1] - 2.0, v[2] - 3.0};
    const double r_i = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    worst_radius = std::max(worst_radius, std::abs(r_i - 1.5));
    for (int k = 0; k < 3; ++k) worst_normal = std::max(worst_normal, std::abs(v[3 + k] - d[k] / r_i));
  }
  // World coordinates (the rendering origin added back), on the sphere, normals pointing out of it.
  EXPECT_LT(worst_radius, 1e-4);
  EXPECT_LT(worst_normal, 1e-4);
}

TEST(ExportMesh, ASceneOfTheExportedFileRendersTheSameImage) {
  const fs::path dir = scratch_dir();
  // At the origin: the file's float coordinates are then those the renderer used, to the bit.
  write_text(dir / "scene.json", scene(sphere("0"), "0"));
  ASSERT_EQ(run_ochre("export-mesh scene.json --shape ball -o ball.ply -q", dir).exit_code, 0);
  write_text(dir / "from_ply.json",
             scene(R"({"type": "mesh", "name": "ball", "file": "ball.ply", "material": "grey"})", "0"));
  for (const char* name : {"scene", "from_ply"}) {
    const CommandResult r = run_ochre(std::string("render ") + name + ".json -o " + name + ".exr -q", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const ExrImage a = read_exr(dir / "scene.exr"), b = read_exr(dir / "from_ply.exr");
  const std::vector<float>&ra = exr_channel(a, "R"), &rb = exr_channel(b, "R");
  ASSERT_EQ(ra.size(), rb.size());
  double sum_a = 0, largest = 0;
  for (size_t i = 0; i < ra.size(); ++i) {
    sum_a += ra[i];
    largest = std::max(largest, double(std::abs(ra[i] - rb[i])));
  }
  // The same triangles, normals and uvs: the same paths (rounding of the positions aside).
  EXPECT_GT(sum_a, 0.0);
  EXPECT_LT(largest, 1e-3 * std::max(1.0, sum_a / double(ra.size())));
}

TEST(ExportMesh, AShapeThatIsNotThereOrNotNamedIsBadInputAndWritesNothing) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", scene(sphere()));
  const CommandResult several = run_ochre("export-mesh scene.json -o out.ply", dir);
  EXPECT_EQ(several.exit_code, 2) << several.output;
  EXPECT_NE(several.output.find("2 meshes ('ball', 'floor'): name one with --shape"), std::string::npos)
      << several.output;
  const CommandResult missing = run_ochre("export-mesh scene.json --shape rock -o out.ply", dir);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("--shape 'rock': no mesh of that name (the scene's meshes: 'ball', 'floor')"),
            std::string::npos)
      << missing.output;
  EXPECT_FALSE(fs::exists(dir / "out.ply"));
}

}  // namespace
}  // namespace ochre::test::export_mesh_test
