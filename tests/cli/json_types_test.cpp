// JSON values of the wrong type or out of range are errors naming the file and the field, never a raw
// nlohmann type_error (exit 1), a wrapped integer or a silently ignored duplicate key
// (docs/scene-format.md, "Validation").
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::json_types_test {
namespace {

const char* kGrey = R"("materials": {"grey": {"type": "lambert", "color": 0.5}})";
const char* kPlane = R"("shapes": [{"type": "plane", "material": "grey"}])";

std::string sphere_with(const std::string& members) {
  return scene_with("/shapes/0", fmt::format(R"({{"type": "sphere", "material": "grey", {}}})", members));
}

std::string mesh_with(const std::string& members) {
  return scene_with("/shapes/0",
                    fmt::format(R"({{"type": "mesh", "file": "{}", "material": "grey", {}}})",
                                (source_dir() / "tests" / "data" / "quad.obj").string(), members));
}

// --- booleans: every boolean field of docs/scene-format.md, given a string, a number and null

TEST(JsonTypes, BooleanFieldsRejectStringsNumbersAndNull) {
  for (const char* value : {"\"yes\"", "1", "0", "null", "\"true\""}) {
    expect_rejected({fmt::format("stokes {}", value),
                     scene_with("/output/stokes", value),
                     {"output.stokes", "expected true or false"}});
    expect_rejected({fmt::format("aovs {}", value),
                     scene_with("/output/aovs", value),
                     {"output.aovs", "expected true or false"}});
    expect_rejected({fmt::format("smooth_normals {}", value),
                     mesh_with(fmt::format(R"("smooth_normals": {})", value)),
                     {"shapes[0].smooth_normals", "expected true or false"}});
    expect_rejected({fmt::format("flip_uv_v {}", value),
                     mesh_with(fmt::format(R"("flip_uv_v": {})", value)),
                     {"shapes[0].flip_uv_v", "expected true or false"}});
  }
}

TEST(JsonTypes, BooleanFieldsAcceptTrueAndFalse) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", mesh_with(R"("smooth_normals": true, "flip_uv_v": false)"));
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// --- duplicate keys

TEST(JsonTypes, DuplicateKeyAtTopLevel) {
  expect_rejected({"top",
                   scene_text(kGrey, kPlane, R"("film": {"resolution": [4, 4]}, )"),
                   {"film", "duplicate key \"film\""}});
}

TEST(JsonTypes, DuplicateKeyInANestedObject) {
  expect_rejected(
      {"nested",
       scene_text(kGrey, R"("shapes": [{"type": "sphere", "radius": 1, "radius": 2, "material": "grey"}])"),
       {"shapes[0].radius", "duplicate key \"radius\""}});
  expect_rejected({"deeper",
                   scene_text(kGrey, kPlane, R"("camera": {"polarizer": {"angle": 10, "angle": 20}}, )"),
                   {"camera.polarizer.angle", "duplicate key \"angle\""}});
}

// A scene whose only light is `lights` (JSON text, not reparsed).
std::string raw_lights(const std::string& lights) {
  return fmt::format(
      R"({{"film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 1}}, {}, {}, "lights": {}}})", kGrey,
      kPlane, lights);
}

TEST(JsonTypes, DuplicateKeyInAnArrayOfObjects) {
  expect_rejected({"lights",
                   raw_lights(R"([{"type": "point", "position": [0, 0, 1], "intensity": 1},
                                  {"type": "point", "position": [0, 0, 1], "intensity": 1, "intensity": 2}])"),
                   {"lights[1].intensity", "duplicate key"}});
}

TEST(JsonTypes, DuplicateKeyInMaterialNodes) {
  expect_rejected({"node key",
                   scene_text(R"("materials": {"m": {"nodes": {
                                   "d": {"type": "lambert", "color": 0.5, "color": 0.7}}, "output": "d"}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"materials.m.nodes.d.color", "duplicate key \"color\""}});
  expect_rejected({"node name",
                   scene_text(R"("materials": {"m": {"nodes": {
                                   "d": {"type": "lambert"}, "d": {"type": "emission"}}, "output": "d"}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"materials.m.nodes.d", "duplicate key \"d\""}});
  expect_rejected(
      {"material name",
       scene_text(R"("materials": {"grey": {"type": "lambert"}, "grey": {"type": "emission"}})", kPlane),
       {"materials.grey", "duplicate key \"grey\""}});
}

TEST(JsonTypes, DuplicateKeyInASpectrumObject) {
  expect_rejected(
      {"spectrum",
       raw_lights(
           R"([{"type": "point", "position": [0, 0, 1], "intensity": {"blackbody": 2000, "blackbody": 3000}}])"),
       {"lights[0].intensity.blackbody", "duplicate key"}});
}

// --- integers: floats, negative, huge and wrapping values, each checked before any conversion

TEST(JsonTypes, IntegerFieldsRejectFractions) {
  expect_rejected(
      {"spp", scene_with("/integrator/spp", R"(2.5)"), {"integrator.spp", "expected an integer", "2.5"}});
  expect_rejected(
      {"resolution", scene_with("/film/resolution", R"([8.5, 8])"), {"film.resolution[0]", "integer"}});
  expect_rejected(
      {"subdivisions", sphere_with(R"("subdivisions": 12.25)"), {"shapes[0].subdivisions", "integer"}});
}

TEST(JsonTypes, IntegerFieldsDoNotWrap) {
  // 4294967297 = 2^32 + 1 would be 1 as a 32-bit integer; 18446744073709551615 = 2^64 - 1 would be -1.
  expect_rejected({"spp", scene_with("/integrator/spp", R"(4294967297)"), {"integrator.spp", "4294967297"}});
  expect_rejected({"resolution", scene_with("/film/resolution", R"([1e12, 2])"), {"film.resolution[0]"}});
  expect_rejected(
      {"resolution 2^32", scene_with("/film/resolution", R"([8, 4294967304])"), {"film.resolution[1]"}});
  expect_rejected({"max_depth", scene_with("/integrator/max_depth", R"(1e300)"), {"integrator.max_depth"}});
  expect_rejected({"seed",
                   scene_with("/integrator/seed", R"(18446744073709551615)"),
                   {"integrator.seed", "18446744073709551615"}});
  expect_rejected({"bins", scene_with("/output/spectral_bins", R"(4294967297)"), {"output.spectral_bins"}});
  expect_rejected(
      {"segments",
       scene_text(kGrey, R"("shapes": [{"type": "disk", "segments": 4294967299, "material": "grey"}])"),
       {"shapes[0].segments"}});
  expect_rejected({"texture channel",
                   scene_text(R"("materials": {"m": {"nodes": {
                                   "t": {"type": "texture", "file": "x.png", "channel": 4294967297},
                                   "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"'m'", "'t'", "channel", "4294967297"}});
}

TEST(JsonTypes, IntegerFieldsRejectNegativeValues) {
  expect_rejected({"seed", scene_with("/integrator/seed", R"(-1)"), {"integrator.seed", "-1"}});
  expect_rejected({"threads", scene_with("/integrator/threads", R"(-5)"), {"integrator.threads", "-5"}});
  expect_rejected({"spp", scene_with("/integrator/spp", R"(-1)"), {"integrator.spp"}});
  expect_rejected({"resolution", scene_with("/film/resolution", R"([-8, 8])"), {"film.resolution[0]"}});
}

TEST(JsonTypes, IntegerWrittenWithAPointZeroIsAnInteger) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene_with("/integrator", R"({"spp": 2.0, "seed": 7.0})"));
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// The command line's integers are checked the same way: CLI11 alone reads --seed -1 as 2^64 - 1.
TEST(JsonTypes, CommandLineIntegersDoNotWrap) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene_with("/integrator/spp", "1"));
  for (const char* args :
       {"--seed -1", "--seed 18446744073709551616", "--exposure 1e39", "--spp 4294967297"}) {
    const CommandResult r = run_ochre(std::string("render scene.json -o out.exr ") + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(std::string(args).substr(0, std::string(args).find(' '))), std::string::npos)
        << args << "\n"
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr")) << args;
  }
  const CommandResult r =
      run_tool("ochre-converge", "scene.json --reference auto --spp 1 --variant a:threads=4294967297", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("threads"), std::string::npos) << r.output;
}

// --- numbers that are finite doubles but not usable single-precision floats

TEST(JsonTypes, NumbersThatUnderflowSinglePrecision) {
  expect_rejected({"radius",
                   sphere_with(R"("radius": 1e-50)"),
                   {"shapes[0].radius", "got 1e-50", "which is 0 in single precision"}});
  expect_rejected({"fov", scene_with("/camera/fov", R"(1e-46)"), {"camera.fov", "0 in single precision"}});
  expect_rejected(
      {"denormal", scene_with("/camera/eye", R"([0, 1e-40, 5])"), {"camera.eye[1]", "smallest normal"}});
  expect_rejected({"intensity",
                   scene_with("/lights", R"([{"type": "point", "position": [0, 0, 1], "intensity": 1e-50}])"),
                   {"lights[0].intensity", "0 in single precision"}});
  expect_rejected({"material literal",
                   scene_text(R"("materials": {"grey": {"type": "lambert", "color": 1e-50}})", kPlane),
                   {"'grey'", "color", "0 in single precision"}});
}

TEST(JsonTypes, NumbersThatOverflowSinglePrecision) {
  expect_rejected(
      {"radius", sphere_with(R"("radius": 1e39)"), {"shapes[0].radius", "infinite in single precision"}});
  expect_rejected({"translate",
                   sphere_with(R"("transform": {"translate": [0, 1e39, 0]})"),
                   {"shapes[0].transform.translate[1]", "infinite in single precision"}});
  expect_rejected({"exposure", scene_with("/output/exposure", R"(1e39)"), {"output.exposure"}});
  expect_rejected(
      {"spectrum scale",
       scene_text(R"("materials": {"m": {"nodes": {"s": {"type": "spectrum", "name": "D65", "scale": 1e39},
                                   "d": {"type": "emission", "color": {"link": "s"}}}, "output": "d"}})",
                  R"("shapes": [{"type": "plane", "material": "m"}])"),
       {"'m'", "'s'", "scale", "infinite in single precision"}});
  expect_rejected(
      {"blackbody scale",
       scene_with(
           "/lights",
           R"([{"type": "point", "position": [0, 0, 1], "intensity": {"blackbody": 2000, "scale": 1e39}}])"),
       {"lights[0].intensity.scale", "infinite in single precision"}});
}

}  // namespace
}  // namespace ochre::test::json_types_test
