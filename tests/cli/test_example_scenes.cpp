// Every example scene shipped in scenes/ (found by walking the folder, so a new scene is covered without
// editing this file) loads with only the repository's files and renders a finite, non-black image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "cli/cli_runner.h"
#include "renderer/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> example_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::recursive_directory_iterator(source_dir() / "scenes"))
    if (entry.is_regular_file() && entry.path().extension() == ".json") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(ExampleScenes, EveryShippedSceneRendersAtLowResolution) {
  const std::vector<fs::path> scenes = example_scenes();
  EXPECT_GE(scenes.size(), 20u);  // the walk found the folder
  for (const fs::path& scene : scenes) {
    const auto dir = scratch_dir();
    const CommandResult r =
        run_ochre("render '" + scene.string() + "' -o " + (dir / "out.exr").string() + " --png " +
                      (dir / "out.png").string() + " --resolution 48x32 --spp 2",
                  dir);
    ASSERT_EQ(r.exit_code, 0) << scene << "\n" << r.output;
    EXPECT_TRUE(fs::exists(dir / "out.png")) << scene;
    const ExrImage image = read_exr(dir / "out.exr");
    double sum = 0;
    bool finite = true;
    for (const char* channel : {"R", "G", "B"}) {
      const std::vector<float>* values = image.find_channel(channel);
      ASSERT_NE(values, nullptr) << scene << ": no channel " << channel;
      for (float v : *values) {
        finite = finite && std::isfinite(v);
        sum += v;
      }
    }
    EXPECT_TRUE(finite) << scene;
    EXPECT_GT(sum, 0.0) << scene << ": a black image";
  }
}

}  // namespace
}  // namespace ochre::test
