#pragma once
// Helpers of the ochre-regress tests (regression_test.cpp, regress_html_test.cpp): the committed suite of
// tests/regression, copies of its scenes into a scratch suite, and running the tool.

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_runner.h"

namespace ochre::test {

// 'path', for a shell command line.
std::string quoted(const std::filesystem::path& path);

CommandResult run_regress(const std::string& args, const std::filesystem::path& dir);

// tests/regression and its scene names (file stems), sorted.
std::filesystem::path suite_dir();
std::vector<std::string> suite_scenes();

// Copies a committed scene and its reference into suite/ (scenes whose files are all inline).
void copy_suite_scene(const std::string& name, const std::filesystem::path& suite);

// dir/suite holding lambert_environment with albedo 0.5 -> 0.55 against the committed reference: it fails.
std::filesystem::path perturbed_suite(const std::filesystem::path& dir);

}  // namespace ochre::test
