#pragma once
// Runs the built `ochre` executable and captures its exit code and combined output.

#include <filesystem>
#include <string>

#include "support/text_files.h"  // write_text for the tests' scenes

namespace ochre::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs `bin_dir()/TOOL ARGS` in `working_dir` (progress output off). stderr is merged into the
// output unless `stdout_only`. With timeout_seconds > 0 the tool is killed (SIGKILL) when it runs
// longer, and exit_code is then 137: for inputs that could make a tool hang.
CommandResult run_tool(const std::string& tool, const std::string& args,
                       const std::filesystem::path& working_dir = {}, bool stdout_only = false,
                       int timeout_seconds = 0);
// Runs a /bin/sh command line in `working_dir` (output as given by the command's own redirections).
CommandResult run_shell(const std::string& shell_command, const std::filesystem::path& working_dir = {});
// Runs `bin_dir()/ochre ARGS` in `working_dir`.
inline CommandResult run_ochre(const std::string& args, const std::filesystem::path& working_dir = {}) {
  return run_tool("ochre", args, working_dir);
}

}  // namespace ochre::test
