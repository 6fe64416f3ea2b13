// Errors found deep inside geometry, transforms, cameras, lights and mesh processing name the scene file
// and the JSON path of the field at fault ("scene.json: shapes[0].radius: ..."), never only the inner
// object ("sphere: radius ..."), and report the value as written, not after its conversion to float.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::error_locations_test {
namespace {

std::string data_file(const char* name) {
  return (source_dir() / "tests" / "data" / name).string();
}

// The scene with shapes[0] replaced by `shape` (JSON text).
std::string with_shape(const std::string& shape) {
  return scene_with("/shapes/0", shape);
}

std::string with_light(const std::string& light) {
  return scene_with("/lights/0", light);
}

TEST(ErrorLocations, SphereRadiusThatIsZeroInSinglePrecision) {
  expect_rejected({"radius",
                   with_shape(R"({"type": "sphere", "radius": 1e-50, "material": "grey"})"),
                   {"scene.json: shapes[0].radius: ", "(got 1e-50, which is 0 in single precision)"}});
}

TEST(ErrorLocations, SphereRadiusThatIsInfiniteInSinglePrecision) {
  expect_rejected({"radius",
                   with_shape(R"({"type": "sphere", "radius": 1e39, "material": "grey"})"),
                   {"scene.json: shapes[0].radius: ", "1e+39", "infinite in single precision"}});
}

TEST(ErrorLocations, DiskRadiusAndPlaneSize) {
  expect_rejected({"disk",
                   with_shape(R"({"type": "disk", "radius": 1e-45, "material": "grey"})"),
                   {"scene.json: shapes[0].radius: "}});
  expect_rejected({"plane",
                   with_shape(R"({"type": "plane", "size": [1, 1e-60], "material": "grey"})"),
                   {"scene.json: shapes[0].size[1]: ", "0 in single precision"}});
}

TEST(ErrorLocations, RotationAxisWhoseLengthOverflows) {
  expect_rejected(
      {"axis",
       with_shape(
           R"({"type": "sphere", "material": "grey", "transform": {"rotate": {"axis": [3e38, 3e38, 0], "angle": 5}}})"),
       {"scene.json: shapes[0].transform.rotate.axis: "}});
}

TEST(ErrorLocations, TransformWhoseScaleUnderflows) {
  expect_rejected({"scale",
                   with_shape(R"({"type": "sphere", "material": "grey", "transform": [{"scale": 1e-20}]})"),
                   {"scene.json: shapes[0].transform: ", "singular"}});
}

TEST(ErrorLocations, GeometryThatOverflowsAfterItsTransform) {
  expect_rejected({"positions",
                   with_shape(R"({"type": "sphere", "radius": 1e30, "material": "grey",
                                 "transform": [{"scale": 1e8}, {"translate": [3e38, 0, 0]}]})"),
                   {"scene.json: shapes[0]: ", "not finite"}});
}

TEST(ErrorLocations, CameraEyeAndTargetTooFarApart) {
  expect_rejected({"camera",
                   scene_with("/camera", R"({"eye": [-1e15, 0, 0], "target": [3e38, 0, 3e38]})"),
                   {"scene.json: camera.target: "}});
}

TEST(ErrorLocations, CameraWithBothTransformAndLookAt) {
  expect_rejected({"camera",
                   scene_with("/camera", R"({"eye": [0, 0, 5], "transform": {"translate": [0, 0, 5]}})"),
                   {"scene.json: camera.transform: ", "not both"}});
}

TEST(ErrorLocations, SpotDirectionWhoseLengthOverflows) {
  expect_rejected(
      {"spot",
       with_light(R"({"type": "spot", "position": [0, 0, 2], "direction": [3e38, 3e38, 0], "intensity": 1})"),
       {"scene.json: lights[0].direction: "}});
}

TEST(ErrorLocations, PolarizerAxisWhoseLengthUnderflows) {
  expect_rejected({"polarizer",
                   with_light(R"({"type": "point", "position": [0, 0, 2], "intensity": 1,
                                 "polarizer": {"axis": [1e-30, 0, 0]}})"),
                   {"scene.json: lights[0].polarizer.axis: "}});
}

TEST(ErrorLocations, LightPowerThatOverflows) {
  expect_rejected({"point",
                   with_light(R"({"type": "point", "position": [0, 0, 2], "intensity": 3e38})"),
                   {"scene.json: lights[0].intensity: ", "overflows"}});
  expect_rejected({"emission",
                   scene_text(R"("materials": {"e": {"type": "emission", "color": 3e38}})",
                              R"("shapes": [{"type": "plane", "material": "e"}])"),
                   {"scene.json: shapes[0]: ", "overflows"}});
}

TEST(ErrorLocations, BlackbodyTooColdToEmitVisibleLight) {
  expect_rejected({"blackbody",
                   with_light(R"({"type": "point", "position": [0, 0, 2], "intensity": {"blackbody": 60}})"),
                   {"scene.json: lights[0].intensity.blackbody: ", "60 K"}});
}

// The scene with shapes[0] a mesh of tests/data/`file` with the members `members`.
std::string with_mesh(const char* file, const std::string& members) {
  return with_shape(
      fmt::format(R"({{"type": "mesh", "file": "{}", "material": "grey", {}}})", data_file(file), members));
}

TEST(ErrorLocations, LoopSubdivisionOfQuads) {
  expect_rejected({"loop",
                   with_mesh("cube_quads.obj", R"("subdivision": {"scheme": "loop", "level": 1})"),
                   {"scene.json: shapes[0].subdivision: ", "cube_quads", "triangles only"}});
}

TEST(ErrorLocations, DisplacementWithoutTextureCoordinates) {
  expect_rejected(
      {"uv",
       with_mesh("tetrahedron.obj", R"("subdivision": {"level": 1}, "displacement": {"file": "h.exr"})"),
       {"scene.json: shapes[0].displacement: ", "texture coordinates"}});
}

TEST(ErrorLocations, DisplacementTextureMissing) {
  expect_rejected(
      {"texture",
       with_mesh("cube_quads.obj", R"("subdivision": {"level": 1}, "displacement": {"file": "h.exr"})"),
       {"scene.json: shapes[0].displacement: ", "h.exr"}});
}

TEST(ErrorLocations, FlipUvIsNotSilentlyIgnoredWithSubdivision) {
  expect_rejected({"flip",
                   with_mesh("cube_quads.obj", R"("flip_uv_v": true, "subdivision": {"level": 1})"),
                   {"scene.json: shapes[0].flip_uv_v: "}});
}

TEST(ErrorLocations, MeshWithoutTriangles) {
  expect_rejected({"no triangles",
                   with_mesh("no_triangles.obj", R"("name": "empty")"),
                   {"scene.json: shapes[0].file: ", "no_triangles.obj"}});
}

TEST(ErrorLocations, StokesOutputNamesTheSceneAndTheMode) {
  auto scene = nlohmann::json::parse(scene_with("/integrator/polarization", R"("off")"));
  scene["output"]["stokes"] = true;
  expect_rejected({"stokes", scene.dump(), {"scene.json: integrator.polarization: ", "'off'"}});
}

}  // namespace
}  // namespace ochre::test::error_locations_test
