#include "tools/vgroove/vgroove_png.h"

#include "renderer/image/display_image.h"

namespace ochre {

void write_map_png(const std::filesystem::path& path, int size, const std::vector<std::uint8_t>& rgb,
                   const std::string& description) {
  write_rgb8(path, "png", size, size, rgb, description);
}

void write_map_png(AtomicOutput& output, int size, const std::vector<std::uint8_t>& rgb,
                   const std::string& description) {
  write_rgb8(output, "png", size, size, rgb, description);
}

}  // namespace ochre
