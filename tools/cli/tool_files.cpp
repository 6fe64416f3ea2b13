#include "tools/cli/tool_files.h"

#include <system_error>

namespace ochre {

namespace fs = std::filesystem;

namespace {

// The directory of the running executable, or empty when it cannot be found.
fs::path executable_dir() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : exe.parent_path();
}

}  // namespace

fs::path tool_file(const fs::path& installed, const fs::path& in_source) {
  if (const fs::path bin = executable_dir(); !bin.empty()) {
    for (const fs::path& candidate :
         {bin / ".." / "share" / "ochre" / installed, bin / ".." / ".." / in_source}) {
      std::error_code error;
      if (fs::exists(candidate, error)) return candidate.lexically_normal();
    }
  }
  return fs::path(OCHRE_SOURCE_DIR) / in_source;
}

}  // namespace ochre
