#include "cli/regress_suite.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) {
  std::string text = "'";  // built by appending: GCC 12 warns falsely on "'" + std::string
  text += path.string();
  text += "'";
  return text;
}

CommandResult run_regress(const std::string& args, const fs::path& dir) {
  return run_tool("ochre-regress", args, dir);
}

fs::path suite_dir() {
  return source_dir() / "tests" / "regression";
}

std::vector<std::string> suite_scenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(suite_dir()))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

void copy_suite_scene(const std::string& name, const fs::path& suite) {
  fs::create_directories(suite / "references");
  fs::copy_file(suite_dir() / (name + ".json"), suite / (name + ".json"),
                fs::copy_options::overwrite_existing);
  fs::copy_file(suite_dir() / "references" / (name + ".exr"), suite / "references" / (name + ".exr"),
                fs::copy_options::overwrite_existing);
}

fs::path perturbed_suite(const fs::path& dir) {
  const fs::path suite = dir / "suite";
  copy_suite_scene("lambert_environment", suite);
  std::string scene = read_file_contents(suite / "lambert_environment.json");
  const std::string from = "\"color\": 0.5";
  const size_t at = scene.find(from);
  EXPECT_NE(at, std::string::npos);
  scene.replace(at, from.size(), "\"color\": 0.55");
  write_text(suite / "lambert_environment.json", scene);
  return suite;
}

}  // namespace ochre::test
