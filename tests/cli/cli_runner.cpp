#include "cli/cli_runner.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>

#include "support/test_paths.h"

namespace ochre::test {

CommandResult run_tool(const std::string& tool, const std::string& args,
                       const std::filesystem::path& working_dir, bool stdout_only, int timeout_seconds) {
  std::string command = "OCHRE_PROGRESS=none ";
  if (timeout_seconds > 0)
    command.append("timeout -s KILL ").append(std::to_string(timeout_seconds)).append(" ");
  command.append("'").append((bin_dir() / tool).string()).append("' ").append(args);
  command.append(stdout_only ? " 2>/dev/null" : " 2>&1");
  return run_shell(command, working_dir);
}

CommandResult run_shell(const std::string& shell_command, const std::filesystem::path& working_dir) {
  std::string command;
  if (!working_dir.empty()) command = "cd '" + working_dir.string() + "' && ";
  command += shell_command;
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace ochre::test
