#include "tools/python_script.h"

#include <cstdlib>

namespace ochre {

namespace {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

fs::path tool_script(std::string_view name) {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path beside = exe.parent_path() / ".." / ".." / "tools" / name;
    if (fs::exists(beside)) return beside;
  }
  return fs::path(OCHRE_SOURCE_DIR) / "tools" / name;
}

bool run_python(const fs::path& script, const std::vector<std::string>& args) {
  std::string command = "/usr/bin/python3 " + shell_quote(script.string());
  for (const std::string& arg : args) command += " " + shell_quote(arg);
  return std::system(command.c_str()) == 0;
}

}  // namespace ochre
