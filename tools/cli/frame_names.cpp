#include "tools/cli/frame_names.h"

#include <fmt/format.h>

#include <filesystem>

namespace ochre {

std::string frame_output_name(const std::string& path, uint64_t frame) {
  const std::filesystem::path p(path);
  const std::string number = fmt::format("{:04d}", frame);
  if (!p.has_extension() || p.stem().empty()) return path + "." + number;
  return (p.parent_path() / (p.stem().string() + "." + number + p.extension().string())).string();
}

}  // namespace ochre
