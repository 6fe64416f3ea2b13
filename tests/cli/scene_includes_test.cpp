// Scene files that include others (materials, shapes, lights), material references that layer another
// material's graph, and presets chosen with --preset (docs/scene-format.md "Including files", "Presets";
// docs/nodes.md "Layering materials"): what they render and every way they can be wrong (exit 2, the file
// and the field named, no output written).
#include <gtest/gtest.h>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::scene_includes_test {
namespace {

namespace fs = std::filesystem;

const char* kGrey = R"({"materials": {"grey": {"type": "lambert", "color": 0.5}}})";
const char* kCamera = R"("camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 3]},
  "film": {"resolution": [8, 8]}, "integrator": {"spp": 1, "max_depth": 1},
  "lights": [{"type": "environment", "radiance": 1}])";

// A scene of the given top-level members around kCamera, in dir/scene.json.
void write_scene(const fs::path& dir, const std::string& members) {
  write_text(dir / "scene.json", std::string("{") + kCamera + ",\n" + members + "}");
}

// The mean luminance (Rec.709 weights) of out.exr: a grey albedo a under a constant environment of
// luminance 1 renders as luminance a.
double mean_luminance(const fs::path& dir) {
  const ExrImage image = read_exr(dir / "out.exr");
  const std::vector<float>&r = *image.find_channel("R"), &g = *image.find_channel("G"),
        &b = *image.find_channel("B");
  double sum = 0;
  for (size_t i = 0; i < g.size(); ++i) sum += 0.2126 * r[i] + 0.7152 * g[i] + 0.0722 * b[i];
  return sum / double(g.size());
}

CommandResult render(const fs::path& dir, const std::string& extra = "") {
  return run_ochre("render scene.json -o out.exr -q --spp 64 " + extra, dir);
}

TEST(SceneIncludes, IncludedMaterialsShapesAndLightsRenderAndPathsStayRelativeToTheirFile) {
  const fs::path dir = scratch_dir();
  // The library lives in a sub-folder and names a spectrum beside itself: the path must resolve there.
  write_text(dir / "lib/half.csv", "wavelength,value\n360,0.5\n830,0.5\n");
  write_text(dir / "lib/library.json",
             R"({"materials": {"half": {"type": "lambert", "color": {"file": "half.csv"}}},
                 "shapes": [{"type": "plane", "size": [4, 4], "material": "half"}]})");
  write_scene(dir, R"("include": ["lib/library.json"])");
  const CommandResult r = render(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(mean_luminance(dir), 0.5, 0.01);  // albedo 0.5 under radiance 1, one bounce
}

TEST(SceneIncludes, AFileIncludedTwiceIsReadOnce) {
  const fs::path dir = scratch_dir();
  write_text(dir / "grey.json", kGrey);
  write_text(dir / "a.json", R"({"include": ["grey.json"]})");
  write_text(dir / "b.json", R"({"include": ["grey.json"]})");
  write_scene(dir, R"("include": ["a.json", "b.json"], "shapes": [{"type": "plane", "material": "grey"}])");
  const CommandResult r = render(dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(SceneIncludes, MaterialReferencesInlineAnotherMaterialsGraph) {
  const fs::path dir = scratch_dir();
  write_text(dir / "lib/tint.csv", "wavelength,value\n360,1\n830,1\n");
  // The referenced material reads a file beside itself; the reference is mixed half and half with black.
  write_text(
      dir / "lib/pigment.json",
      R"({"materials": {"pigment": {"nodes": {"s": {"type": "spectrum", "file": "tint.csv", "scale": 0.8},
                  "l": {"type": "lambert", "color": {"link": "s"}}}, "output": "l"}}})");
  write_scene(dir, R"("include": ["lib/pigment.json"],
    "materials": {"layered": {"nodes": {"p": {"type": "material", "material": "pigment"},
                                        "black": {"type": "lambert", "color": 0},
                                        "out": {"type": "mix", "a": {"link": "black"}, "b": {"link": "p"}, "factor": 0.5}},
                              "output": "out"},
                  "copy": {"type": "material", "material": "pigment"}},
    "shapes": [{"type": "plane", "size": [4, 4], "material": "layered"}])");
  CommandResult r = render(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(mean_luminance(dir), 0.4, 0.01);
  // The same scene named by a relative path from elsewhere: the inlined node still finds its file.
  r = run_ochre("render " + dir.filename().string() + "/scene.json -o " + dir.filename().string() +
                    "/out.exr -q --spp 64",
                dir.parent_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(mean_luminance(dir), 0.4, 0.01);
  // A whole material that is a reference is a copy.
  write_scene(
      dir,
      R"("include": ["lib/pigment.json"], "materials": {"copy": {"type": "material", "material": "pigment"}},
    "shapes": [{"type": "plane", "size": [4, 4], "material": "copy"}])");
  r = render(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(mean_luminance(dir), 0.8, 0.01);
}

TEST(SceneIncludes, PresetsPatchSettingsAndNamedShapes) {
  const fs::path dir = scratch_dir();
  write_scene(
      dir,
      R"("materials": {"grey": {"type": "lambert", "color": 0.5}, "white": {"type": "lambert", "color": 1}},
    "shapes": [{"name": "wall", "type": "plane", "size": [4, 4], "material": "grey"}],
    "presets": {"fast": {"description": "as written"},
                "big": {"film": {"resolution": [16, 4]}, "shapes": {"wall": {"material": "white"}}}})");
  CommandResult r = render(dir, "--preset fast");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(mean_luminance(dir), 0.5, 0.01);
  r = render(dir, "--preset big");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage image = read_exr(dir / "out.exr");
  EXPECT_EQ(image.width, 16);
  EXPECT_EQ(image.height, 4);
  EXPECT_NEAR(mean_luminance(dir), 1.0, 0.01);
  // The command line overrides the preset.
  r = render(dir, "--preset big --resolution 6x6");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_exr(dir / "out.exr").width, 6);
}

// --- Bad input: one test per way an include, a reference or a preset can be wrong. ---------------------

void expect_bad(const fs::path& dir, const std::string& members, const std::vector<std::string>& expected,
                const std::string& extra = "") {
  write_scene(dir, members);
  const CommandResult r = run_ochre("render scene.json -o out.exr --png out.png " + extra, dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const std::string& text : expected)
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

const char* kPlane = R"("shapes": [{"name": "wall", "type": "plane", "material": "grey"}])";

TEST(SceneIncludesBad, MissingIncludedFile) {
  expect_bad(scratch_dir(), std::string(R"("include": ["nope.json"], )") + kPlane,
             {"scene.json: include[0]", "nope.json", "cannot open included scene file"});
}

TEST(SceneIncludesBad, IncludeIsNotAnArrayOfNames) {
  const fs::path dir = scratch_dir();
  expect_bad(dir, std::string(R"("include": "grey.json", )") + kPlane, {"scene.json: include", "array"});
  expect_bad(dir, std::string(R"("include": [3], )") + kPlane, {"scene.json: include[0]"});
  expect_bad(dir, std::string(R"("include": [""], )") + kPlane, {"scene.json: include[0]", "empty"});
}

TEST(SceneIncludesBad, MalformedIncludedFileIsNamed) {
  const fs::path dir = scratch_dir();
  write_text(dir / "broken.json", "{\"materials\": {");
  expect_bad(dir, std::string(R"("include": ["broken.json"], )") + kPlane,
             {"include[0]", "broken.json", "malformed JSON"});
}

TEST(SceneIncludesBad, IncludeCycleListsTheChain) {
  const fs::path dir = scratch_dir();
  write_text(dir / "a.json", R"({"include": ["b.json"]})");
  write_text(dir / "b.json", R"({"include": ["a.json"]})");
  expect_bad(dir, std::string(R"("include": ["a.json"], )") + kPlane,
             {"b.json: include[0]", "includes itself", "a.json -> b.json -> a.json"});
}

TEST(SceneIncludesBad, IncludedFileMayNotSetMainSceneKeys) {
  const fs::path dir = scratch_dir();
  for (const char* key : {"camera", "film", "integrator", "output", "presets"}) {
    write_text(dir / "lib.json", std::string(R"({")") + key + R"(": {}})");
    expect_bad(dir, std::string(R"("include": ["lib.json"], )") + kPlane,
               {std::string("lib.json: ") + key, "only the main scene file"});
  }
  write_text(dir / "lib.json", R"({"glitter": 1})");
  expect_bad(dir, std::string(R"("include": ["lib.json"], )") + kPlane,
             {"lib.json: glitter", "unknown parameter"});
}

TEST(SceneIncludesBad, MaterialDefinedInTwoFiles) {
  const fs::path dir = scratch_dir();
  write_text(dir / "grey.json", kGrey);
  expect_bad(
      dir,
      std::string(R"("include": ["grey.json"], "materials": {"grey": {"type": "lambert", "color": 0.2}}, )") +
          kPlane,
      {"scene.json: materials.grey", "also defined in", "grey.json"});
}

TEST(SceneIncludesBad, ErrorsInAnIncludedFileNameThatFile) {
  const fs::path dir = scratch_dir();
  write_text(dir / "lib.json", R"({"materials": {"grey": {"type": "lambert", "color": -1}},
                                   "shapes": [{"type": "sphere", "radius": -2, "material": "grey"}]})");
  expect_bad(dir, R"("include": ["lib.json"])", {"lib.json", "'grey'", "color"});
  write_text(dir / "lib.json", R"({"materials": {"grey": {"type": "lambert", "color": 0.5}},
                                   "shapes": [{"type": "sphere", "radius": -2, "material": "grey"}]})");
  expect_bad(dir, R"("include": ["lib.json"])", {"lib.json: shapes[0].radius"});
  write_text(dir / "lib.json", R"({"lights": [{"type": "point", "position": [0, 0, 1], "intensity": -1}]})");
  expect_bad(
      dir,
      std::string(R"("include": ["lib.json"], "materials": {"grey": {"type": "lambert", "color": 0.5}}, )") +
          kPlane,
      {"lib.json: lights[0].intensity"});
}

TEST(SceneIncludesBad, NoShapesAnywhere) {
  expect_bad(scratch_dir(), R"("materials": {"grey": {"type": "lambert", "color": 0.5}})",
             {"scene.json: shapes", "expected an array of shapes"});
}

TEST(SceneIncludesBad, UnknownReferencedMaterial) {
  expect_bad(
      scratch_dir(),
      R"("materials": {"grey": {"nodes": {"p": {"type": "material", "material": "nope"}}, "output": "p"}},
    "shapes": [{"type": "plane", "material": "grey"}])",
      {"scene.json: materials.grey.nodes.p.material", "unknown material 'nope'"});
}

TEST(SceneIncludesBad, ReferenceWithExtraKeys) {
  expect_bad(scratch_dir(), R"("materials": {"a": {"type": "lambert"},
    "grey": {"nodes": {"p": {"type": "material", "material": "a", "color": 1}}, "output": "p"}},
    "shapes": [{"type": "plane", "material": "grey"}])",
             {"materials.grey.nodes.p.color", "unknown parameter"});
}

TEST(SceneIncludesBad, ReferenceCycle) {
  expect_bad(
      scratch_dir(),
      R"("materials": {"a": {"type": "material", "material": "b"}, "b": {"type": "material", "material": "a"},
    "grey": {"type": "lambert"}}, "shapes": [{"type": "plane", "material": "grey"}])",
      {"cycle", "'a' -> 'b' -> 'a'"});
}

TEST(SceneIncludesBad, InlinedNodeNameTaken) {
  expect_bad(
      scratch_dir(),
      R"("materials": {"lib": {"nodes": {"c": {"type": "lambert"}, "o": {"type": "multiply", "a": {"link": "c"}, "b": 0.5}}, "output": "o"},
    "grey": {"nodes": {"p": {"type": "material", "material": "lib"}, "p/c": {"type": "lambert"}}, "output": "p"}},
    "shapes": [{"type": "plane", "material": "grey"}])",
      {"materials.grey.nodes.p", "'p/c', which is taken"});
}

TEST(SceneIncludesBad, UnknownPreset) {
  expect_bad(
      scratch_dir(),
      std::string(R"("materials": {"grey": {"type": "lambert"}}, "presets": {"fast": {}, "final": {}}, )") +
          kPlane,
      {"scene.json: presets", "no preset 'huge'", "known: fast, final"}, "--preset huge");
}

TEST(SceneIncludesBad, PresetAskedOfASceneWithout) {
  expect_bad(scratch_dir(), std::string(R"("materials": {"grey": {"type": "lambert"}}, )") + kPlane,
             {"scene.json: presets", "no presets", "'final'"}, "--preset final");
}

TEST(SceneIncludesBad, PresetsAreCheckedEvenWhenNotChosen) {
  const fs::path dir = scratch_dir();
  const std::string materials = R"("materials": {"grey": {"type": "lambert"}}, )";
  expect_bad(dir, materials + R"("presets": {"final": {"integrater": {}}}, )" + kPlane,
             {"scene.json: presets.final.integrater", "unknown parameter"});
  expect_bad(dir, materials + R"("presets": {"final": {"film": 3}}, )" + kPlane,
             {"scene.json: presets.final.film", "expected a JSON object"});
  expect_bad(dir, materials + R"("presets": {"final": {"shapes": {"wal": {}}}}, )" + kPlane,
             {"scene.json: presets.final.shapes.wal", "no shape is named 'wal'"});
  expect_bad(dir, materials + R"("presets": {"final": 2}, )" + kPlane, {"scene.json: presets.final"});
}

TEST(SceneIncludesBad, BadValueFromAPresetNamesThePreset) {
  expect_bad(
      scratch_dir(),
      std::string(
          R"("materials": {"grey": {"type": "lambert"}}, "presets": {"final": {"integrator": {"spp": 0}}}, )") +
          kPlane,
      {"scene.json: integrator.spp", "with preset 'final'", "presets.final"}, "--preset final");
}

}  // namespace
}  // namespace ochre::test::scene_includes_test
