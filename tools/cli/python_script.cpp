#include "tools/cli/python_script.h"

#include <cstdlib>

#include "tools/cli/tool_files.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) {
    if (c == '\'')
      quoted.append("'\\''");
    else
      quoted.push_back(c);
  }
  quoted.push_back('\'');
  return quoted;
}

}  // namespace

fs::path tool_script(std::string_view name) {
  return tool_file(fs::path("scripts") / name, fs::path("tools") / "scripts" / name);
}

bool run_python(const fs::path& script, const std::vector<std::string>& args) {
  std::string command = "/usr/bin/python3 ";
  command.append(shell_quote(script.string()));
  for (const std::string& arg : args) {
    command.push_back(' ');
    command.append(shell_quote(arg));
  }
  return std::system(command.c_str()) == 0;
}

}  // namespace ochre
