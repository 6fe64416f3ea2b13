// Lights and emission never emit negative radiance: every way of writing a negative light spectrum is
// rejected (exit 2, the scene file, the field and, for a CSV, the wavelength of its first negative entry),
// and emission that varies over a surface counts as 0 where a texture makes it negative
// (docs/scene-format.md, "Validation").
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "renderer/image/exr_writer.h"
#include "support/test_paths.h"

namespace ochre::test::negative_light_test {
namespace {

const char* kGrey = R"("materials": {"grey": {"type": "lambert", "color": 0.5}})";
const char* kPlane = R"("shapes": [{"type": "plane", "material": "grey"}])";

// A scene lit only by `light` (a JSON object).
std::string lit_by(const std::string& light) {
  return fmt::format(
      R"({{"film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 1}}, {}, {}, "lights": [{}]}})", kGrey,
      kPlane, light);
}

// A plane whose material is `material` (a JSON object named "e"), in a constant environment.
std::string emitting(const std::string& material) {
  return scene_text(fmt::format(R"("materials": {{"e": {}}})", material),
                    R"("shapes": [{"type": "plane", "material": "e"}])");
}

// A scratch directory holding neg.csv (negative everywhere, first at 400 nm) and cross.csv (positive at
// the ends, crossing zero to -0.2 at 550 nm).
std::filesystem::path dir_with_csvs() {
  const auto dir = scratch_dir();
  write_text(dir / "neg.csv", "wavelength,value\n400,-0.5\n500,-1\n700,-0.5\n");
  write_text(dir / "cross.csv", "wavelength,value\n400,1\n500,0.5\n550,-0.2\n600,0.5\n700,1\n");
  return dir;
}

TEST(NegativeLight, EnvironmentCsv) {
  expect_rejected({"env csv",
                   lit_by(R"({"type": "environment", "radiance": {"file": "neg.csv"}})"),
                   {"lights[0].radiance.file", "neg.csv", "-0.5 at 400 nm"}},
                  dir_with_csvs());
}

TEST(NegativeLight, EnvironmentConstant) {
  expect_rejected({"env constant",
                   lit_by(R"({"type": "environment", "radiance": -1})"),
                   {"lights[0].radiance", "must be >= 0", "-1"}});
}

TEST(NegativeLight, EnvironmentRgb) {
  expect_rejected({"env rgb",
                   lit_by(R"({"type": "environment", "radiance": [1, -0.1, 1]})"),
                   {"lights[0].radiance", "must be >= 0"}});
}

TEST(NegativeLight, EnvironmentScale) {
  expect_rejected({"env scale",
                   lit_by(R"({"type": "environment", "radiance": 1, "scale": -2})"),
                   {"lights[0].scale", ">= 0"}});
}

TEST(NegativeLight, EnvironmentNamedSpectrumScaledNegatively) {
  expect_rejected({"env named",
                   lit_by(R"({"type": "environment", "radiance": {"name": "D65", "scale": -1}})"),
                   {"lights[0].radiance.scale", ">= 0"}});
}

TEST(NegativeLight, EnvironmentMapTexel) {
  const auto dir = scratch_dir();
  ExrImage map;
  map.width = 4;
  map.height = 2;
  for (const char* channel : {"R", "G", "B"}) map.channels.push_back({channel, std::vector<float>(8, 1.0f)});
  map.channels[1].second[5] = -0.25f;  // G of column 1, row 1
  write_exr(dir / "sky.exr", map);
  expect_rejected({"env map",
                   lit_by(R"({"type": "environment", "file": "sky.exr"})"),
                   {"lights[0].file", "sky.exr", "texel (column 1, row 1) is negative"}},
                  dir);
}

TEST(NegativeLight, PointZeroCrossingCsv) {
  expect_rejected({"point csv",
                   lit_by(R"({"type": "point", "position": [0, 0, 2], "intensity": {"file": "cross.csv"}})"),
                   {"lights[0].intensity.file", "cross.csv", "-0.2 at 550 nm"}},
                  dir_with_csvs());
}

TEST(NegativeLight, PointConstant) {
  expect_rejected({"point constant",
                   lit_by(R"({"type": "point", "position": [0, 0, 2], "intensity": -3})"),
                   {"lights[0].intensity", ">= 0"}});
}

TEST(NegativeLight, PointBlackbodyScaledNegatively) {
  expect_rejected(
      {"point blackbody",
       lit_by(R"({"type": "point", "position": [0, 0, 2], "intensity": {"blackbody": 2700, "scale": -5}})"),
       {"lights[0].intensity.scale", ">= 0"}});
}

TEST(NegativeLight, SpotScaledCsvNamesTheTableEntry) {
  expect_rejected({"spot csv",
                   lit_by(R"({"type": "spot", "position": [0, 0, 2], "direction": [0, 0, -1],
                              "intensity": {"file": "cross.csv", "scale": 10}})"),
                   {"lights[0].intensity.file", "cross.csv", "-0.2 at 550 nm"}},
                  dir_with_csvs());
}

TEST(NegativeLight, SpotRgb) {
  expect_rejected({"spot rgb",
                   lit_by(R"({"type": "spot", "position": [0, 0, 2], "target": [0, 0, 0],
                              "intensity": [-1, 1, 1]})"),
                   {"lights[0].intensity", "must be >= 0"}});
}

TEST(NegativeLight, EmissionConstantStrength) {
  expect_rejected(
      {"strength", emitting(R"({"type": "emission", "strength": -2})"), {"'e'", "strength", "negative"}});
}

TEST(NegativeLight, EmissionRgbColour) {
  expect_rejected({"rgb emission",
                   emitting(R"({"type": "emission", "color": [1, -1, 1]})"),
                   {"'e'", "color", "negative"}});
}

TEST(NegativeLight, EmissionZeroCrossingCsv) {
  expect_rejected({"emission csv",
                   emitting(R"({"type": "emission", "color": {"file": "cross.csv"}})"),
                   {"'e'", "color", "-0.2 at 550 nm"}},
                  dir_with_csvs());
}

TEST(NegativeLight, EmissionNamedSpectrumScaledNegatively) {
  expect_rejected({"emission named",
                   emitting(R"({"type": "emission", "color": {"name": "D65", "scale": -1}})"),
                   {"'e'", "color", "scale"}});
}

TEST(NegativeLight, EmissionFromSpectrumNode) {
  expect_rejected({"spectrum node",
                   emitting(R"({"nodes": {"s": {"type": "spectrum", "file": "neg.csv"},
                                          "glow": {"type": "emission", "color": {"link": "s"}}},
                                "output": "glow"})"),
                   {"'e'", "'glow'", "color", "-0.5 at 400 nm"}},
                  dir_with_csvs());
}

TEST(NegativeLight, EmissionFromAConstantNegativeProduct) {
  expect_rejected({"product",
                   emitting(R"({"nodes": {"m": {"type": "multiply", "a": {"name": "D65"}, "b": -1},
                                          "glow": {"type": "emission", "color": {"link": "m"}}},
                                "output": "glow"})"),
                   {"'e'", "'glow'", "color", "negative"}});
}

// A texture cannot be checked when the scene loads (it is read lazily): emission made negative by texels
// counts as 0. Here every texel is -1, so without the clamp every pixel seeing the plane would be < 0.
TEST(NegativeLight, TexturedEmissionIsClampedToZeroAtRunTime) {
  const auto dir = scratch_dir();
  ExrImage texture;
  texture.width = texture.height = 2;
  for (const char* channel : {"R", "G", "B"})
    texture.channels.push_back({channel, std::vector<float>(4, -1.0f)});
  write_exr(dir / "negative.exr", texture);
  write_text(dir / "scene.json", R"({"film": {"resolution": [8, 8]}, "integrator": {"spp": 4},
    "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "fov": 30},
    "materials": {"e": {"nodes": {
      "t": {"type": "texture", "file": "negative.exr", "colorspace": "linear"},
      "m": {"type": "multiply", "a": {"name": "D65"}, "b": {"link": "t.value"}},
      "glow": {"type": "emission", "color": {"link": "m"}}}, "output": "glow"}},
    "shapes": [{"type": "plane", "size": [4, 4], "material": "e"}]})");
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage image = read_exr(dir / "out.exr");
  for (const char* channel : {"R", "G", "B"})
    for (float v : *image.find_channel(channel)) EXPECT_EQ(v, 0.0f) << channel;
}

}  // namespace
}  // namespace ochre::test::negative_light_test
