// Photogrammetry in scenes (docs/scene-format.md "Meshes with several materials",
// docs/guide/cave-painting.md): an OBJ whose MTL has several materials and texture atlases becomes one mesh
// per material, mapped to scene materials by name, with each MTL material's textures available to a template
// material ("mtl:map_Kd"); pigment painted onto a real rock-art scan (the external Mont Bego PLY, vertex
// colours, no uvs) through a projected mask.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::photogrammetry_test {
namespace {

namespace fs = std::filesystem;

// Two quads filling x in [-2, 2], y in [-1, 1] at z = 0: the left one uses MTL material atlas_left
// (texture left.ppm, red), the right one atlas_right (right.ppm, blue), as a scan with two atlases.
void write_two_atlas_scan(const fs::path& dir) {
  write_text(dir / "scan.obj", R"(mtllib scan.mtl
v -2 -1 0
v 0 -1 0
v 0 1 0
v -2 1 0
v 2 -1 0
v 2 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl atlas_left
f 1/1 2/2 3/3 4/4
usemtl atlas_right
f 2/1 5/2 6/3 3/4
)");
  write_text(
      dir / "scan.mtl",
      "newmtl atlas_left\nKd 1 1 1\nmap_Kd left.ppm\nnewmtl atlas_right\nKd 1 1 1\nmap_Kd right.ppm\n");
  write_text(dir / "left.ppm", "P3\n2 2\n255\n200 20 20 200 20 20 200 20 20 200 20 20\n");
  write_text(dir / "right.ppm", "P3\n2 2\n255\n20 20 200 20 20 200 20 20 200 20 20 200\n");
}

const char* kView = R"("camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 3]},
  "film": {"resolution": [16, 8]}, "integrator": {"spp": 16, "max_depth": 1},
  "lights": [{"type": "environment", "radiance": {"name": "D65"}}])";

const char* kTemplate =
    R"("scan": {"nodes": {"atlas": {"type": "texture", "file": "mtl:map_Kd", "colorspace": "linear"},
                                       "d": {"type": "lambert", "color": {"link": "atlas.color"}}}, "output": "d"})";

struct Halves {
  double left_r = 0, left_b = 0, right_r = 0, right_b = 0;
};

Halves mean_halves(const fs::path& exr) {
  const ExrImage image = read_exr(exr);
  const std::vector<float>&r = *image.find_channel("R"), &b = *image.find_channel("B");
  Halves h;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t i = size_t(y) * image.width + x;
      (x < image.width / 2 ? h.left_r : h.right_r) += r[i];
      (x < image.width / 2 ? h.left_b : h.right_b) += b[i];
    }
  return h;
}

TEST(Photogrammetry, EachMtlMaterialGetsItsOwnTexturesThroughATemplate) {
  const fs::path dir = scratch_dir();
  write_two_atlas_scan(dir);
  write_text(dir / "scene.json", std::string("{") + kView + R"(, "materials": {)" + kTemplate + R"(},
    "shapes": [{"name": "wall", "type": "mesh", "file": "scan.obj", "materials": {"*": "scan"}}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 meshes"), std::string::npos) << r.output;  // not merged into one
  const Halves h = mean_halves(dir / "out.exr");
  EXPECT_GT(h.left_r, 4 * h.left_b);    // the red atlas on the left
  EXPECT_GT(h.right_b, 4 * h.right_r);  // the blue atlas on the right
}

TEST(Photogrammetry, MtlMaterialsMapToSceneMaterialsByName) {
  const fs::path dir = scratch_dir();
  write_two_atlas_scan(dir);
  write_text(dir / "scene.json", std::string("{") + kView + R"(, "materials": {
      "green": {"type": "lambert", "color": [0.1, 0.8, 0.1]}, )" +
                                     kTemplate + R"(},
    "shapes": [{"type": "mesh", "file": "scan.obj", "materials": {"atlas_left": "green", "*": "scan"}}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Halves h = mean_halves(dir / "out.exr");
  EXPECT_LT(h.left_r, 0.3 * h.right_b);  // the left half is the green material, not the red atlas
  EXPECT_GT(h.right_b, 4 * h.right_r);
}

TEST(Photogrammetry, AMaterialThatLayersATemplateIsATemplateToo) {
  const fs::path dir = scratch_dir();
  write_two_atlas_scan(dir);
  write_text(dir / "scene.json", std::string("{") + kView + R"(, "materials": {)" + kTemplate + R"(,
      "black": {"type": "lambert", "color": 0},
      "faded": {"nodes": {"scan": {"type": "material", "material": "scan"},
                          "black": {"type": "material", "material": "black"},
                          "out": {"type": "mix", "a": {"link": "black"}, "b": {"link": "scan"}, "factor": 0.5}},
                "output": "out"}},
    "shapes": [{"type": "mesh", "file": "scan.obj", "materials": {"*": "faded"}}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Halves h = mean_halves(dir / "out.exr");
  EXPECT_GT(h.left_r, 4 * h.left_b);
  EXPECT_GT(h.right_b, 4 * h.right_r);
}

void expect_bad_scan(const std::string& materials, const std::string& shape,
                     const std::vector<std::string>& expected) {
  const fs::path dir = scratch_dir();
  write_two_atlas_scan(dir);
  expect_rejected(
      {"scan",
       std::string("{") + kView + R"(, "materials": {)" + materials + "}, \"shapes\": [" + shape + "]}",
       expected},
      dir);
}

TEST(PhotogrammetryBad, UnmappedFileMaterial) {
  expect_bad_scan(
      kTemplate, R"({"type": "mesh", "file": "scan.obj", "materials": {"atlas_left": "scan"}})",
      {"scene.json: shapes[0].materials", "'atlas_right' is not mapped", "'atlas_left', 'atlas_right'"});
}

TEST(PhotogrammetryBad, MappingNamesAMaterialTheFileLacks) {
  expect_bad_scan(kTemplate,
                  R"({"type": "mesh", "file": "scan.obj", "materials": {"*": "scan", "atlas_x": "scan"}})",
                  {"scene.json: shapes[0].materials.atlas_x", "no material 'atlas_x'"});
}

TEST(PhotogrammetryBad, UnknownSceneMaterial) {
  expect_bad_scan(kTemplate, R"({"type": "mesh", "file": "scan.obj", "materials": {"*": "nope"}})",
                  {"scene.json: shapes[0].materials.*", "unknown material 'nope'"});
}

TEST(PhotogrammetryBad, TemplateKeywordTheMtlMaterialLacks) {
  expect_bad_scan(
      R"("scan": {"nodes": {"t": {"type": "texture", "file": "mtl:map_Ks"},
                      "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"})",
      R"({"type": "mesh", "file": "scan.obj", "materials": {"*": "scan"}})",
      {"scene.json: shapes[0].materials.*", "'atlas_left' has no map_Ks texture", "it has: map_Kd"});
}

TEST(PhotogrammetryBad, TemplateUsedAsAPlainMaterial) {
  expect_bad_scan(kTemplate, R"({"type": "plane", "material": "scan"})",
                  {"scene.json: shapes[0].material", "'scan' is a template"});
}

TEST(PhotogrammetryBad, MaterialAndMaterialsTogether) {
  expect_bad_scan(kTemplate,
                  R"({"type": "mesh", "file": "scan.obj", "material": "scan", "materials": {"*": "scan"}})",
                  {"scene.json: shapes[0].materials", "not both"});
}

TEST(PhotogrammetryBad, MaterialsMapOnAProceduralShape) {
  expect_bad_scan(kTemplate, R"({"type": "plane", "materials": {"*": "scan"}})",
                  {"scene.json: shapes[0]", "materials"});
}

TEST(PhotogrammetryBad, MissingAtlasTexture) {
  const fs::path dir = scratch_dir();
  write_two_atlas_scan(dir);
  fs::remove(dir / "right.ppm");
  expect_rejected({"atlas",
                   std::string("{") + kView + R"(, "materials": {)" + kTemplate +
                       R"(}, "shapes": [{"type": "mesh", "file": "scan.obj", "materials": {"*": "scan"}}]})",
                   {"'scan@atlas_right'", "'atlas'", "right.ppm"}},
                  dir);
}

// The Mont Bego rock-art scan (vertex colours, no uvs; external assets, never committed) painted with
// hematite through the default scene's bison mask projected along the scan's z axis (its relief). Rendered
// with and without the paint: only pixels inside the projected frame change, and they turn redder.
TEST(Photogrammetry, PigmentProjectedOntoTheMontBegoScan) {
  OCHRE_REQUIRE_SHARED();
  const fs::path ply = shared_dir() / "assets/meshes/mont-bego/7_1_8.ply";
  if (!fs::exists(ply)) GTEST_SKIP() << "no " << ply;
  const fs::path mask = source_dir() / "scenes/default/paint_hematite_fine.png";
  const fs::path dir = scratch_dir();
  auto scene = [&](double paint) {
    return R"({"camera": {"type": "orthographic", "size": 56, "eye": [0, 0, 60], "target": [0, 0, 0]},
      "film": {"resolution": [96, 96]}, "integrator": {"spp": 8, "max_depth": 1},
      "lights": [{"type": "environment", "radiance": {"name": "D65"}}],
      "materials": {"scan": {"nodes": {
        "colour": {"type": "vertex_colour"},
        "rock": {"type": "lambert_sphere", "kd": {"link": "colour"}},
        "frame": {"type": "projection", "origin": [-20, -20, 0], "u_axis": [40, 0, 0], "v_axis": [0, 20, 0], "depth": 100},
        "mask": {"type": "texture", "file": ")" +
           mask.string() +
           R"(", "colorspace": "linear", "uv": {"link": "frame.uv"}, "footprint": {"link": "frame.footprint"}},
        "cover": {"type": "multiply", "a": {"link": "mask.value"}, "b": {"link": "frame.inside"}},
        "amount": {"type": "multiply", "a": {"link": "cover"}, "b": )" +
           std::to_string(paint) + R"(},
        "hematite": {"type": "powder", "radius": 0.05, "volume_amplitude": 2},
        "out": {"type": "mix", "a": {"link": "rock"}, "b": {"link": "hematite"}, "factor": {"link": "amount"}}},
        "output": "out"}},
      "shapes": [{"type": "mesh", "file": ")" +
           ply.string() + R"(", "material": "scan", "smooth_normals": true}]})";
  };
  write_text(dir / "bare.json", scene(0));
  write_text(dir / "painted.json", scene(1));
  ASSERT_EQ(run_ochre("render bare.json -o bare.exr -q", dir).exit_code, 0);
  const CommandResult r = run_ochre("render painted.json -o painted.exr -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage bare = read_exr(dir / "bare.exr"), painted = read_exr(dir / "painted.exr");
  int changed = 0, redder = 0, outside_frame = 0;
  for (int y = 0; y < bare.height; ++y)
    for (int x = 0; x < bare.width; ++x) {
      const size_t i = size_t(y) * bare.width + x;
      auto at = [&](const ExrImage& image, const char* c) { return (*image.find_channel(c))[i]; };
      if (at(bare, "R") == at(painted, "R") && at(bare, "G") == at(painted, "G") &&
          at(bare, "B") == at(painted, "B"))
        continue;
      ++changed;
      const double wx = -28 + (x + 0.5) * 56.0 / 96,
                   wy = 28 - (y + 0.5) * 56.0 / 96;                            // pixel centre in world
      if (wx < -20.6 || wx > 20.6 || wy < -20.6 || wy > 0.6) ++outside_frame;  // half a pixel of slack
      const double rb = at(bare, "R") / std::max(1e-6f, at(bare, "G")),
                   rp = at(painted, "R") / std::max(1e-6f, at(painted, "G"));
      if (rp > rb) ++redder;
    }
  EXPECT_GT(changed, 100) << "the paint is not visible";
  EXPECT_EQ(outside_frame, 0) << "paint outside the projected frame";
  EXPECT_GT(redder, changed * 9 / 10) << redder << " of " << changed << " changed pixels are redder";
}

}  // namespace
}  // namespace ochre::test::photogrammetry_test
