// ochre-bench end to end: the ratio against raw Embree over interleaved rounds, with its median and range,
// and bad input (a missing scene) as exit 2 naming the file. Timings are printed, never asserted.

#include <gtest/gtest.h>

#include <regex>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::ochre_bench_test {
namespace {

TEST(OchreBench, RoundsGiveAMedianRatioWithItsRange) {
  const std::string scene = (source_dir() / "scenes" / "furnace" / "furnace.json").string();
  const CommandResult r =
      run_tool("ochre-bench", "\"" + scene + "\" --spp 1 --seconds 0.05 --repeat 3 --threads 2", {}, true);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("3 round(s)"), std::string::npos) << r.output;
  // One renderer line and one raw line per round, then Embree's defaults once.
  size_t renderer_lines = 0, raw_lines = 0;
  for (size_t at = 0; (at = r.output.find("  renderer:", at)) != std::string::npos; ++at) ++renderer_lines;
  for (size_t at = 0; (at = r.output.find("renderer's BVH options", at)) != std::string::npos; ++at)
    ++raw_lines;
  EXPECT_EQ(renderer_lines, 3u) << r.output;
  EXPECT_EQ(raw_lines, 3u) << r.output;
  EXPECT_NE(r.output.find("Embree's default options"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("median of 3 rounds"), std::string::npos) << r.output;
  // The median lies within the printed range.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.output, m,
      std::regex(R"(ratio renderer/raw rays/s: ([0-9.]+) % \(range ([0-9.]+) \.\. ([0-9.]+) %)")))
      << r.output;
  const double median = std::stod(m[1]), low = std::stod(m[2]), high = std::stod(m[3]);
  EXPECT_GT(median, 0.0);
  EXPECT_LE(low, median);
  EXPECT_LE(median, high);
  EXPECT_NE(r.output.find("of thread time in Embree queries"), std::string::npos) << r.output;
}

TEST(OchreBench, MissingSceneExitsTwoNamingIt) {
  const CommandResult r = run_tool("ochre-bench", "no_such_scene.json --seconds 0.05", scratch_dir());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no_such_scene.json"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ochre::test::ochre_bench_test
