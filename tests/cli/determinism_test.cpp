// Renders are deterministic: the same scene and seed give bit-identical images for any
// thread count; different seeds give different images.
#include <gtest/gtest.h>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::determinism_test {
namespace {

ExrImage render_cornell(const std::string& args) {
  const auto dir = scratch_dir();
  const auto scene = source_dir() / "scenes/cornell-box/cornell-box.json";
  const CommandResult r = run_ochre("render '" + scene.string() + "' -o " + (dir / "out.exr").string() +
                                        " --resolution 40x40 --spp 8 " + args,
                                    dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return read_exr(dir / "out.exr");
}

TEST(Determinism, BitIdenticalForAnyThreadCount) {
  const ExrImage one = render_cornell("--threads 1");
  const ExrImage two = render_cornell("--threads 2");
  const ExrImage four = render_cornell("--threads 4");
  EXPECT_TRUE(same_rgb_values(one, two));
  EXPECT_TRUE(same_rgb_values(one, four));
}

// A branched render (integrator.branches) says how many paths it traces per pixel.
TEST(Determinism, BranchedRenderReportsItsPathsPerPixel) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", scene_with("/integrator/branches", "3"));
  const CommandResult r = run_ochre("render scene.json -o out.exr --spp 4 --resolution 8x8", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("8x8, 4 spp x 3 branches (12 paths per pixel), max depth"), std::string::npos)
      << r.output;
}

TEST(Determinism, SeedChangesTheNoise) {
  EXPECT_FALSE(same_rgb_values(render_cornell("--seed 1"), render_cornell("--seed 2")));
}

}  // namespace
}  // namespace ochre::test::determinism_test
