// NaN and infinities at shading time never crash a render (docs/nodes.md, "Non-finite values"): every way
// one can arise in a valid scene (vertex colours and arithmetic that overflow, texels, huge uvs, lobes fed
// them, emission) renders with exit 0, a finite EXR, and the count of values made finite in the statistics
// line and the EXR header. Files holding NaN or infinities where the scene format forbids them (mesh
// attributes, environment map texels, displaced positions) are rejected at load with exit 2, naming the file
// and what is wrong.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "renderer/image/exr_writer.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::nonfinite_values_test {
namespace {

namespace fs = std::filesystem;

constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

// The scene of the defect report: vertex colour x 3e38 x 10 is infinite. It exited 139 (SIGSEGV).
constexpr const char* kIssueScene =
    R"({"film":{"resolution":[16,16]},"integrator":{"spp":1},"materials":{"m":{"nodes":{"vc":{"type":"vertex_colour"},"big":{"type":"multiply","a":{"link":"vc.color"},"b":3e38},"inf":{"type":"multiply","a":{"link":"big"},"b":10},"out":{"type":"lambert","color":{"link":"inf"}}},"output":"out"}},"lights":[{"type":"environment","radiance":1}],"shapes":[{"type":"sphere","material":"m"}]})";

// Nodes producing an infinite colour "inf" (and a float "inf_value") at run time.
constexpr const char* kOverflow = R"(
    "vc": {"type": "vertex_colour"},
    "big": {"type": "multiply", "a": {"link": "vc.color"}, "b": 3e38},
    "inf": {"type": "multiply", "a": {"link": "big"}, "b": 10},
    "inf_value": {"type": "multiply", "a": 3e38, "b": {"link": "big_value"}},
    "big_value": {"type": "multiply", "a": 3e38, "b": {"link": "one.value"}},
    "one": {"type": "texture", "file": "one.exr", "channel": 0})";

// A scene under a white environment and a point light (so that next-event estimation picks between
// lights): material "m" is made of `nodes` with output "out"; "grey" is diffuse. By default a sphere of "m".
std::string scene_with(const std::string& nodes,
                       const std::string& shapes = R"([{"type": "sphere", "material": "m"}])") {
  return fmt::format(R"({{"film": {{"resolution": [16, 16]}}, "integrator": {{"spp": 2, "max_depth": 4}},
    "camera": {{"eye": [0, 0, 4]}},
    "materials": {{"m": {{"nodes": {{{}}}, "output": "out"}}, "grey": {{"type": "lambert"}}}},
    "lights": [{{"type": "environment", "radiance": 1}}, {{"type": "point", "position": [2, 2, 2], "intensity": 5}}],
    "shapes": {}}})",
                     nodes, shapes);
}

// A linear RGB EXR of 4 x 4 texels cycling through `values`.
void write_texture(const fs::path& path, const std::vector<float>& values) {
  ExrImage image;
  image.width = image.height = 4;
  for (const char* name : {"B", "G", "R"}) {
    std::vector<float> plane(16);
    for (size_t i = 0; i < plane.size(); ++i) plane[i] = values[i % values.size()];
    image.channels.emplace_back(name, std::move(plane));
  }
  write_exr(path, image);
}

// Writes the textures every scene here may use: one.exr (all 1), bad.exr (NaN, +inf, -inf, 0.5 texels).
fs::path scene_dir() {
  const fs::path dir = scratch_dir();
  write_texture(dir / "one.exr", {1.0f});
  write_texture(dir / "bad.exr", {kNaN, kInf, -kInf, 0.5f});
  return dir;
}

struct Rendered {
  CommandResult result;
  uint64_t made_finite = 0;  // from the statistics line
};

// Renders dir/scene.json; the render must succeed with a finite image whose header repeats the count.
Rendered render_finite(const fs::path& dir, const std::string& scene) {
  write_text(dir / "scene.json", scene);
  Rendered r;
  r.result = run_ochre("render scene.json -o out.exr --aovs", dir);
  EXPECT_EQ(r.result.exit_code, 0) << r.result.output;
  if (r.result.exit_code != 0) return r;
  std::smatch m;
  const std::regex stats(R"((\d+) discarded NaN/Inf samples, (\d+) NaN/Inf shading values made finite)");
  EXPECT_TRUE(std::regex_search(r.result.output, m, stats)) << r.result.output;
  if (m.empty()) return r;
  r.made_finite = std::stoull(m[2].str());
  const ExrImage exr = read_exr(dir / "out.exr");
  for (const auto& [name, values] : exr.channels) {
    size_t non_finite = 0;
    for (float v : values) non_finite += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(non_finite, 0u) << "channel " << name;
  }
  EXPECT_EQ(exr.string_attributes.at("ochre.nonFiniteShadingValues"), m[2].str());
  EXPECT_EQ(exr.string_attributes.at("ochre.discardedSamples"), m[1].str());
  return r;
}

void expect_rejected(const fs::path& dir, const std::string& scene,
                     const std::vector<std::string>& expected) {
  write_text(dir / "scene.json", scene);
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const std::string& s : expected)
    EXPECT_NE(r.output.find(s), std::string::npos) << "message must contain '" << s << "'\n" << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

TEST(NonFiniteValues, IssueSceneRendersFinite) {
  const auto dir = scratch_dir();
  EXPECT_GT(render_finite(dir, kIssueScene).made_finite, 0u);
}

TEST(NonFiniteValues, ValidSceneMakesNothingFinite) {
  const auto dir = scene_dir();
  const Rendered r =
      render_finite(dir, scene_with(R"("out": {"type": "lambert", "color": [0.8, 0.4, 0.2]})"));
  EXPECT_EQ(r.made_finite, 0u);
  EXPECT_NE(r.result.output.find(" 0 discarded NaN/Inf samples, 0 NaN/Inf shading values made finite"),
            std::string::npos)
      << r.result.output;
}

TEST(NonFiniteValues, OverflowThroughAdd) {
  const auto dir = scene_dir();
  EXPECT_GT(render_finite(dir, scene_with(R"("vc": {"type": "vertex_colour"},
      "big": {"type": "multiply", "a": {"link": "vc.color"}, "b": 3e38},
      "sum": {"type": "add", "a": {"link": "big"}, "b": {"link": "big"}},
      "out": {"type": "lambert", "color": {"link": "sum"}})"))
                .made_finite,
            0u);
}

TEST(NonFiniteValues, TextureWithNonFiniteTexels) {
  const auto dir = scene_dir();
  EXPECT_GT(render_finite(dir, scene_with(R"("t": {"type": "texture", "file": "bad.exr"},
      "out": {"type": "lambert", "color": {"link": "t.color"}})"))
                .made_finite,
            0u);
}

// Each closure fed an overflow and NaN / infinite texels through its colour and its float inputs.
TEST(NonFiniteValues, EveryClosureFedNonFiniteInputs) {
  const auto dir = scene_dir();
  const std::string sources = std::string(kOverflow) + R"(, "t": {"type": "texture", "file": "bad.exr"})";
  const std::vector<std::string> closures = {
      R"({"type": "lambert_sphere", "kd": {"link": "inf"}})",
      R"({"type": "lambert_sphere", "kd": {"link": "t.color"}, "variant": "exact"})",
      R"({"type": "lambert_sphere", "particle_albedo": {"link": "t.color"}, "variant": "fast"})",
      R"({"type": "oren_nayar", "color": {"link": "inf"}, "sigma": {"link": "inf_value"}})",
      R"({"type": "oren_nayar", "color": {"link": "t.color"}, "sigma": {"link": "t.value"}})",
      R"({"type": "conductor", "eta": {"link": "inf_value"}, "k": {"link": "t.value"}, "roughness": {"link": "t.value"}})",
      R"({"type": "conductor", "eta": {"link": "t.value"}, "k": {"link": "t.value"}})",
      R"({"type": "dielectric", "ior": {"link": "inf_value"}, "roughness": {"link": "t.value"}})",
      R"({"type": "chandrasekhar", "albedo": {"link": "t.color"}})",
  };
  for (const std::string& closure : closures) {
    SCOPED_TRACE(closure);
    EXPECT_GT(render_finite(dir, scene_with(sources + R"(, "out": )" + closure)).made_finite, 0u);
  }
}

TEST(NonFiniteValues, EmissionFedInfinity) {
  const auto dir = scene_dir();
  // An emitting plane (an area light whose power estimate overflows) facing a diffuse sphere.
  const std::string shapes = R"([{"type": "sphere", "material": "grey"},
      {"type": "plane", "material": "m",
       "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 180}}, {"translate": [0, 0, 2]}]}])";
  EXPECT_GT(render_finite(dir, scene_with(std::string(kOverflow) + R"(,
      "out": {"type": "emission", "color": {"link": "inf"}, "strength": {"link": "inf_value"}})",
                                          shapes))
                .made_finite,
            0u);
  EXPECT_GT(render_finite(dir, scene_with(R"("t": {"type": "texture", "file": "bad.exr"},
      "out": {"type": "emission", "color": {"link": "t.color"}, "strength": {"link": "t.value"}})",
                                          shapes))
                .made_finite,
            0u);
}

// A binary little-endian PLY triangle with float positions, uvs and colours (ASCII PLY has no NaN).
void write_ply(const fs::path& path, const std::array<std::array<float, 2>, 3>& uv,
               const std::array<std::array<float, 3>, 3>& rgb) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
         "property float x\nproperty float y\nproperty float z\nproperty float u\nproperty float v\n"
         "property float red\nproperty float green\nproperty float blue\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float positions[3][3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  for (int i = 0; i < 3; ++i) {
    out.write(reinterpret_cast<const char*>(positions[i]), sizeof(positions[i]));
    out.write(reinterpret_cast<const char*>(uv[i].data()), sizeof(float) * 2);
    out.write(reinterpret_cast<const char*>(rgb[i].data()), sizeof(float) * 3);
  }
  const unsigned char count = 3;
  const int32_t indices[3] = {0, 1, 2};
  out.write(reinterpret_cast<const char*>(&count), 1);
  out.write(reinterpret_cast<const char*>(indices), sizeof(indices));
}

const std::array<std::array<float, 2>, 3> kUsualUvs = {{{0, 0}, {1, 0}, {0.5f, 1}}};
const std::array<std::array<float, 3>, 3> kGreys = {
    {{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}}};

std::string mesh_scene(const std::string& nodes) {
  return scene_with(nodes, R"([{"type": "mesh", "file": "scan.ply", "material": "m"}])");
}

TEST(NonFiniteValues, PlyWithNonFiniteVertexColoursIsRejected) {
  for (float bad : {kNaN, kInf}) {
    const auto dir = scene_dir();
    write_ply(dir / "scan.ply", kUsualUvs, {{{0.5f, 0.5f, 0.5f}, {0.5f, bad, 0.5f}, {0.5f, 0.5f, 0.5f}}});
    expect_rejected(dir, mesh_scene(R"("vc": {"type": "vertex_colour"},
                        "out": {"type": "lambert", "color": {"link": "vc.color"}})"),
                    {"scene.json", "shapes[0]", "scan.ply", "colour of vertex 1 is not finite"});
  }
}

// A normal whose length overflows single precision (3e38, 3e38, 0) is still a direction: the mesh loads
// and renders (it used to be normalised in single precision into zero and refused as "zero").
TEST(NonFiniteValues, PlyWithHugeNormals) {
  const auto dir = scene_dir();
  write_text(dir / "scan.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
             "property list uchar int vertex_indices\nend_header\n"
             "0 0 0 3e38 3e38 0\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  render_finite(dir, mesh_scene(R"("out": {"type": "lambert", "color": 0.5})"));
}

TEST(NonFiniteValues, PlyWithHugeVertexColours) {
  const auto dir = scene_dir();
  write_ply(dir / "scan.ply", kUsualUvs, {{{3e38f, 1.0f, 0.0f}, {3e38f, 3e38f, 3e38f}, {0.5f, 0.5f, 0.5f}}});
  render_finite(dir, mesh_scene(R"("vc": {"type": "vertex_colour"},
      "out": {"type": "lambert", "color": {"link": "vc.color"}})"));
}

TEST(NonFiniteValues, MeshWithNonFiniteUvsIsRejected) {
  for (float bad : {kNaN, -kInf}) {
    const auto dir = scene_dir();
    write_ply(dir / "scan.ply", {{{0, 0}, {bad, 0}, {0.5f, 1}}}, kGreys);
    expect_rejected(dir, mesh_scene(R"("t": {"type": "texture", "file": "one.exr"},
                        "out": {"type": "lambert", "color": {"link": "t.color"}})"),
                    {"scene.json", "shapes[0]", "scan.ply", "uv of vertex 1 is not finite"});
  }
}

TEST(NonFiniteValues, MeshWithHugeUvs) {
  const auto dir = scene_dir();
  write_ply(dir / "scan.ply", {{{1e30f, -3e38f}, {3.4e38f, 0}, {-1e30f, 1e20f}}}, kGreys);
  render_finite(dir, mesh_scene(R"("t": {"type": "texture", "file": "bad.exr"},
      "out": {"type": "lambert", "color": {"link": "t.color"}})"));
}

TEST(NonFiniteValues, EnvironmentMapWithNonFiniteTexelsIsRejected) {
  const auto dir = scene_dir();
  write_texture(dir / "sky.exr", {1.0f, 2.0f, kNaN});
  write_text(dir / "scene.json", R"({"film": {"resolution": [8, 8]},
      "materials": {"m": {"type": "lambert"}}, "shapes": [{"type": "sphere", "material": "m"}],
      "lights": [{"type": "environment", "file": "sky.exr"}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const char* s : {"scene.json", "lights[0].file", "sky.exr", "texel (column 2, row 0) is not finite"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

TEST(NonFiniteValues, DisplacementByNonFiniteTexelsIsRejected) {
  const auto dir = scene_dir();
  expect_rejected(
      dir,
      R"({"film": {"resolution": [8, 8]}, "materials": {"m": {"type": "lambert"}},
      "lights": [{"type": "environment", "radiance": 1}],
      "shapes": [{"type": "mesh", "file": ")" +
          (source_dir() / "tests/data/cube_quads.obj").string() +
          R"(", "material": "m", "subdivision": {"level": 1},
                  "displacement": {"file": "bad.exr", "colorspace": "linear", "scale": 0.1}}]})",
      {"scene.json", "shapes[0].displacement", "cube_quads", "position of vertex 0 is not finite"});
}

// Values that saturate are refused or reported, never silently: a sky whose power overflows single
// precision (each sample would be infinite) is refused naming the field; samples beyond the film's range
// (radiance 1e30) are clamped and the render says so, in a warning and in the EXR's header.
TEST(NonFiniteValues, SaturatingValuesAreRefusedOrReported) {
  const auto sky = [](const std::string& radiance) {
    return fmt::format(
        R"({{"camera": {{"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]}},
      "film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 4}},
      "materials": {{"m": {{"type": "lambert", "color": 0.5}}}},
      "lights": [{{"type": "environment", "radiance": {}}}],
      "shapes": [{{"type": "plane", "size": [1, 1], "material": "m"}}]}})",
        radiance);
  };
  const auto dir = scratch_dir();
  write_text(dir / "overflow.json", sky("3e38"));
  const CommandResult overflow = run_ochre("render overflow.json -o overflow.exr -q", dir);
  EXPECT_EQ(overflow.exit_code, 2) << overflow.output;
  EXPECT_NE(
      overflow.output.find("overflow.json: lights[0].radiance: the light's power overflows single precision"),
      std::string::npos)
      << overflow.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "overflow.exr"));

  write_text(dir / "bright.json", sky("1e30"));
  const CommandResult bright = run_ochre("render bright.json -o bright.exr -q", dir);
  ASSERT_EQ(bright.exit_code, 0) << bright.output;
  EXPECT_NE(bright.output.find(
                "ochre: warning: 256 of 256 samples exceeded the film's range and were clamped to 1e+15"),
            std::string::npos)
      << bright.output;
  const ExrImage image = read_exr(dir / "bright.exr");
  ASSERT_TRUE(image.string_attributes.count("ochre.clampedSamples"));
  EXPECT_EQ(image.string_attributes.at("ochre.clampedSamples"), "256");

  write_text(dir / "plain.json", sky("1"));
  const CommandResult plain = run_ochre("render plain.json -o plain.exr -q", dir);
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find("warning"), std::string::npos) << plain.output;
  EXPECT_FALSE(read_exr(dir / "plain.exr").string_attributes.count("ochre.clampedSamples"));
}

}  // namespace
}  // namespace ochre::test::nonfinite_values_test
