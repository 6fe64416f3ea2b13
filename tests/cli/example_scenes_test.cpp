// Every example scene shipped in scenes/ (found by walking the folder, so a new scene is covered without
// editing this file) loads with only the repository's files and renders a finite, non-black image. Files
// that other scenes include (a pigment library, the default cave) are fragments, not scenes: they are
// rendered through the scenes that include them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::example_scenes_test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> json_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(source_dir() / "scenes"))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The files some shipped file names in its "include" list.
std::set<fs::path> included_files(const std::vector<fs::path>& files) {
  std::set<fs::path> included;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, true, true);
    for (const auto& name : json.value("include", nlohmann::json::array()))
      included.insert(fs::weakly_canonical(file.parent_path() / name.get<std::string>()));
  }
  return included;
}

std::vector<fs::path> example_scenes() {
  const std::vector<fs::path> files = json_files();
  const std::set<fs::path> fragments = included_files(files);
  std::vector<fs::path> scenes;
  for (const fs::path& file : files)
    if (!fragments.count(fs::weakly_canonical(file))) scenes.push_back(file);
  return scenes;
}

TEST(ExampleScenes, FragmentsAreIncludedAndEveryLibraryPigmentIsInTheSwatches) {
  const std::set<fs::path> fragments = included_files(json_files());
  EXPECT_TRUE(fragments.count(fs::weakly_canonical(source_dir() / "scenes/default/cave.json")));
  for (const auto& entry : fs::directory_iterator(source_dir() / "scenes/pigments")) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "swatches.json") continue;
    EXPECT_TRUE(fragments.count(fs::weakly_canonical(entry.path()))) << entry.path() << " is in no scene";
  }
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
}  // namespace ochre::test::example_scenes_test
