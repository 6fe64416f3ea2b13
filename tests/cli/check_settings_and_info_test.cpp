// `ochre render --check-settings` and `ochre info` (docs/cli.md), the checks and reports ochre-slurm builds
// on (docs/distributed.md, "Slurm"): the first checks a command line against a scene's settings without
// loading its geometry, refusing what the render would refuse before its first sample, and writes nothing;
// the second says what partial-sum files and checkpoints hold, reading their headers only.

#include <gtest/gtest.h>

#include <filesystem>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::check_settings_and_info_test {
namespace {

namespace fs = std::filesystem;

// A scene whose mesh file does not exist: only a whole load finds that out.
const char* kScene = R"({
  "film": {"resolution": [40, 30]},
  "integrator": {"spp": 16},
  "materials": {"grey": {"type": "lambert", "color": [0.5, 0.5, 0.5]}},
  "lights": [{"type": "point", "position": [0, 2, 2], "intensity": 10}],
  "shapes": [{"type": "mesh", "file": "missing.obj", "material": "grey"}],
  "presets": {"final": {"film": {"resolution": [80, 60]}, "integrator": {"spp": 64, "noise_threshold": 0.02}}}
})";

fs::path scene_dir() {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", kScene);
  return dir;
}

TEST(CheckSettings, PrintsWhatWouldBeRenderedWithoutLoadingTheGeometry) {
  const fs::path dir = scene_dir();
  const CommandResult render = run_ochre("render scene.json -o out.exr -q", dir);
  EXPECT_EQ(render.exit_code, 2) << "the mesh file is missing: " << render.output;

  const CommandResult plain = run_ochre("render scene.json --check-settings", dir);
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output, "scene.json: 40x30, 16 spp, noise threshold 0\n");
  const CommandResult part = run_ochre(
      "render scene.json --check-settings --spp 8 --frames 1 --first-frame 7 --fps 30 --part 1/2 --tile "
      "1/2x1 "
      "-o p.exr",
      dir);
  EXPECT_EQ(part.exit_code, 0) << part.output;
  EXPECT_EQ(
      part.output,
      "scene.json: 40x30, 8 spp, noise threshold 0, frame 7 at 30 fps, samples 4:8 of region 20,0,40,30 "
      "(partial sums)\n");
  const CommandResult preset = run_ochre("render scene.json --check-settings --preset final --frames 3", dir);
  EXPECT_EQ(preset.exit_code, 0) << preset.output;
  EXPECT_EQ(preset.output, "scene.json: 80x60, 64 spp, noise threshold 0.02, frames 1 to 3 at 24 fps\n");
  EXPECT_EQ(fs::directory_iterator(dir)->path().filename(), "scene.json");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "nothing written";
}

TEST(CheckSettings, RefusesWhatTheRenderRefusesBeforeItsFirstSample) {
  const fs::path dir = scene_dir();
  const auto expect_refused = [&](const std::string& args, const std::string& message) {
    const CommandResult r = run_ochre("render scene.json --check-settings " + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    EXPECT_TRUE(contains(r.output, message)) << args << ": " << r.output;
  };
  expect_refused("--part 0/17 -o p.exr", "--part 0/17: more parts than the 16 samples per pixel");
  expect_refused("--preset final --part 0/2 -o p.exr", "--part cannot split a noise-threshold render");
  expect_refused("--tile 0/41x1 -o p.exr", "--tile 0/41x1: more columns or rows than the 40x30 image");
  expect_refused("--part 0/2", "give -o PART.exr");
  expect_refused("--frames 2 --fps 0", "--fps: must be a number in (0, 10000]");
  expect_refused("--frames 2 --part 0/2 -o p.exr", "--part: not with --frames 2");
  expect_refused("--preset draft", "draft");
  expect_refused("--resume out.checkpoint.exr", "--check-settings: not with --resume");
}

TEST(Info, SaysWhatPartsHoldAndNamesAFileItCannotRead) {
  const fs::path dir = scratch_dir();
  const std::string cornell =
      "render '" + (source_dir() / "scenes/cornell-box/cornell-box.json").string() + "' --resolution 16x8 -q";
  ASSERT_EQ(run_ochre(cornell + " --spp 4 --tile 1/2x1 -o tile.exr", dir).exit_code, 0);
  ASSERT_EQ(run_ochre(cornell + " --spp 4 -o image.exr", dir).exit_code, 0);
  const CommandResult r = run_ochre("info tile.exr image.exr tile.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(
      contains(r.output, "tile.exr: partial sums, region 8,0,16,8 of 16x8, samples 0:4 (4 per pixel)\n"))
      << r.output;
  EXPECT_TRUE(
      contains(r.output, "ochre: error: image.exr: ochre.partialSums: missing: not a partial-sum file"))
      << r.output;
  EXPECT_NE(r.output.find("tile.exr: partial sums"), r.output.rfind("tile.exr: partial sums"))
      << "the files after the one it cannot read are listed: " << r.output;
}

}  // namespace
}  // namespace ochre::test::check_settings_and_info_test
