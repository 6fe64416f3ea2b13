#include "tools/vgroove/vgroove_scratch_dir.h"

#include <fmt/format.h>
#include <unistd.h>

namespace ochre {

ScratchDir::ScratchDir(const std::filesystem::path& base)
    : path_(base.string() + fmt::format(".tmp-{}", static_cast<long>(::getpid()))),
      registration_(path_, TemporaryKind::kDirectory) {
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace ochre
