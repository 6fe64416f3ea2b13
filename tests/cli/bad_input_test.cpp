// Every bad-input path of `ochre render`: exit code 2, a message naming the file and the
// node / parameter at fault, and no output file (an existing file is left untouched).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::bad_input_test {
namespace {

const char* kGoodMaterials = R"("materials": {"grey": {"type": "lambert", "color": 0.5}})";
const char* kGoodShapes = R"("shapes": [{"type": "plane", "material": "grey"}])";

TEST(BadInput, MalformedJson) {
  expect_rejected(
      {"json", "{\"film\": {\"resolution\": [8, 8]},\n  \"shapes\": [}", {"line 2", "malformed JSON"}});
}

TEST(BadInput, MissingMesh) {
  expect_rejected(
      {"mesh",
       scene_text(kGoodMaterials, R"("shapes": [{"type": "mesh", "file": "nope.obj", "material": "grey"}])"),
       {"shapes[0]", "nope.obj"}});
}

TEST(BadInput, MissingTexture) {
  expect_rejected(
      {"texture",
       scene_text(R"("materials": {"rock": {"nodes": {"tex": {"type": "texture", "file": "missing.png"},
                     "d": {"type": "lambert", "color": {"link": "tex.color"}}}, "output": "d"}})",
                  R"("shapes": [{"type": "plane", "material": "rock"}])"),
       {"rock", "tex", "missing.png"}});
}

TEST(BadInput, UnknownNodeType) {
  expect_rejected({"node",
                   scene_text(R"("materials": {"m": {"nodes": {"x": {"type": "glitter"}}, "output": "x"}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"'m'", "'x'", "glitter"}});
}

TEST(BadInput, TypeMismatch) {
  expect_rejected({"type",
                   scene_text(R"("materials": {"m": {"nodes": {
                     "a": {"type": "lambert", "color": 0.5},
                     "b": {"type": "lambert", "color": {"link": "a"}}}, "output": "b"}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"'m'", "'b'", "color"}});
}

TEST(BadInput, Cycle) {
  expect_rejected({"cycle",
                   scene_text(R"("materials": {"m": {"nodes": {
                     "a": {"type": "multiply", "a": {"link": "b"}, "b": 0.5},
                     "b": {"type": "multiply", "a": {"link": "a"}, "b": 0.5},
                     "d": {"type": "lambert", "color": {"link": "a"}}}, "output": "d"}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"'m'", "cycle"}});
}

TEST(BadInput, NegativeReflectance) {
  expect_rejected({"negative",
                   scene_text(R"("materials": {"m": {"type": "lambert", "color": -0.5}})",
                              R"("shapes": [{"type": "plane", "material": "m"}])"),
                   {"'m'", "color"}});
}

TEST(BadInput, InfiniteParameter) {
  // 1e300 is a double but +Inf as the float the renderer uses.
  expect_rejected(
      {"inf",
       scene_text(kGoodMaterials, R"("shapes": [{"type": "sphere", "radius": 1e300, "material": "grey"}])"),
       {"shapes[0].radius", "finite"}});
}

TEST(BadInput, NumberOverflowingJson) {
  // JSON has no Inf or NaN literal; 1e999 overflows the parser.
  expect_rejected(
      {"overflow",
       scene_text(kGoodMaterials, R"("shapes": [{"type": "sphere", "radius": 1e999, "material": "grey"}])"),
       {"overflow"}});
}

TEST(BadInput, NaNAsString) {
  expect_rejected(
      {"nan",
       scene_text(kGoodMaterials, R"("shapes": [{"type": "sphere", "radius": "NaN", "material": "grey"}])"),
       {"shapes[0].radius"}});
}

TEST(BadInput, NegativeRadius) {
  expect_rejected(
      {"radius",
       scene_text(kGoodMaterials, R"("shapes": [{"type": "sphere", "radius": -1, "material": "grey"}])"),
       {"shapes[0].radius"}});
}

TEST(BadInput, ZeroResolution) {
  expect_rejected({"resolution",
                   R"({"film": {"resolution": [0, 8]}, "materials": {"g": {"type": "lambert"}},
                   "shapes": [{"type": "plane", "material": "g"}]})",
                   {"resolution"}});
}

TEST(BadInput, BranchesOutOfRange) {
  for (const char* value : {"0", "-2", "65"})
    expect_rejected({std::string("branches ") + value,
                     scene_with("/integrator/branches", value),
                     {"integrator.branches", "must be an integer in [1, 64]"}});
  expect_rejected({"branches 1.5",
                   scene_with("/integrator/branches", "1.5"),
                   {"integrator.branches", "expected an integer, got 1.5"}});
}

TEST(BadInput, UnknownParameter) {
  expect_rejected(
      {"param",
       scene_text(kGoodMaterials, R"("shapes": [{"type": "sphere", "radius": 1, "materal": "grey"}])"),
       {"shapes[0]", "materal"}});
}

TEST(BadInput, UnknownMaterialReference) {
  expect_rejected({"material",
                   scene_text(kGoodMaterials, R"("shapes": [{"type": "plane", "material": "gold"}])"),
                   {"shapes[0].material", "gold"}});
}

TEST(BadInput, MissingSceneFile) {
  const auto dir = scratch_dir();
  const CommandResult r = run_ochre("render absent.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("absent.json"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(BadInput, OutputDirectoryMissing) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene_text(kGoodMaterials, kGoodShapes));
  const CommandResult r = run_ochre("render scene.json -o no/such/dir/out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no/such/dir"), std::string::npos) << r.output;
}

TEST(BadInput, BadResolutionFlag) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene_text(kGoodMaterials, kGoodShapes));
  const CommandResult r = run_ochre("render scene.json -o out.exr --resolution 0x10", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--resolution"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(BadInput, ExistingOutputSurvivesAFailedRender) {
  const auto dir = scratch_dir();
  write_text(dir / "out.exr", "precious");
  write_text(dir / "scene.json",
             scene_text(R"("materials": {"m": {"type": "lambert", "color": -1}})", kGoodShapes));
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  std::ifstream in(dir / "out.exr");
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "precious");
}

TEST(Cli, HelpExitsZero) {
  const CommandResult r = run_ochre("render --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--spp"), std::string::npos);
}

}  // namespace
}  // namespace ochre::test::bad_input_test

namespace ochre::test::bad_input_test {
namespace {

TEST(BadInput, UnknownProgressStyle) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", R"({"film": {"resolution": [4, 4]}, "materials": {"g": {"type": "lambert"}},
    "shapes": [{"type": "plane", "material": "g"}]})");
  const std::string command = "cd '" + dir.string() + "' && OCHRE_PROGRESS=fancy '" +
                              (bin_dir() / "ochre").string() +
                              "' render scene.json -o out.exr > log.txt 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2);
  std::ifstream log(dir / "log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("OCHRE_PROGRESS"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace ochre::test::bad_input_test
