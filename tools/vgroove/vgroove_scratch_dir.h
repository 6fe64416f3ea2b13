#pragma once
// A scratch directory of ochre-vgroove (panels of a map grid, scenes of a comparison): created on
// construction, removed with everything in it when it goes out of scope, or by the signal handler
// (renderer/util/signal_cleanup.h) when the tool is interrupted.

#include <filesystem>

#include "renderer/util/signal_cleanup.h"

namespace ochre {

class ScratchDir {
 public:
  // Creates `base` + ".tmp-<pid>".
  explicit ScratchDir(const std::filesystem::path& base);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  TemporaryFileRegistration registration_;
};

}  // namespace ochre
