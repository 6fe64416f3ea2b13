// Every tool's --version prints the version of project(VERSION) in CMakeLists.txt, the one source of
// the version number, and rendered EXR files record it (the installed tools are checked by
// tests/install/install_test.cmake).

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::version_test {
namespace {

std::string cmake_project_version() {
  std::ifstream in(source_dir() / "CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string s = text.str();
  if (!std::regex_search(s, m, std::regex(R"(project\(ochre VERSION ([0-9]+\.[0-9]+\.[0-9]+))"))) return "";
  return m[1];
}

TEST(Version, EveryToolPrintsTheVersionOfCMakeLists) {
  const std::string version = cmake_project_version();
  ASSERT_FALSE(version.empty()) << "no project(ochre VERSION x.y.z) in CMakeLists.txt";
  for (const char* tool : {"ochre", "ochre-diff", "ochre-regress", "ochre-converge", "ochre-bench",
                           "ochre-brdf", "ochre-halfspace", "ochre-vgroove"}) {
    const CommandResult r = run_tool(tool, "--version");
    EXPECT_EQ(r.exit_code, 0) << tool << ": " << r.output;
    EXPECT_EQ(r.output, std::string(tool) + " " + version + "\n") << tool;
  }
}

TEST(Version, RenderedExrRecordsTheVersionOfCMakeLists) {
  const auto dir = scratch_dir();
  const auto scene = source_dir() / "scenes" / "furnace" / "furnace.json";
  const CommandResult r =
      run_ochre("render '" + scene.string() + "' -o out.exr --resolution 4x2 --spp 1 -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_exr(dir / "out.exr").string_attributes.at("software"), "ochre " + cmake_project_version());
}

}  // namespace
}  // namespace ochre::test::version_test
