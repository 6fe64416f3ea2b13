#pragma once
// The tools' plotting scripts (C++ writes CSV, Python draws): found like every run-time file of the tools
// (tool_files.h: share/ochre/scripts when installed, else tools/scripts/ in the source tree), and run with
// /usr/bin/python3 (Debian python3-matplotlib).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ochre {

std::filesystem::path tool_script(std::string_view name);

// Runs /usr/bin/python3 SCRIPT ARGS... (each argument shell-quoted); true when it exited with 0.
bool run_python(const std::filesystem::path& script, const std::vector<std::string>& args);

}  // namespace ochre
