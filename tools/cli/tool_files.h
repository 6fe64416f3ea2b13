#pragma once
// Files the tools read at run time (the plot scripts, the example scenes), found in this order:
//   installed tree: <prefix>/share/ochre/<installed>, the executable being in <prefix>/bin;
//   build tree inside the source tree: <source>/<in_source>, the executable being in <source>/build/bin;
//   the source tree the tool was built from: OCHRE_SOURCE_DIR/<in_source> (may no longer exist).

#include <filesystem>

namespace ochre {

std::filesystem::path tool_file(const std::filesystem::path& installed,
                                const std::filesystem::path& in_source);

}  // namespace ochre
