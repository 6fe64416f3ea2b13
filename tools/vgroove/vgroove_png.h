#pragma once
// Writes a square 8-bit RGB map as PNG (renderer/image/display_image.h, atomically).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ochre {

class AtomicOutput;

void write_map_png(const std::filesystem::path& path, int size, const std::vector<std::uint8_t>& rgb,
                   const std::string& description);
// The same into output.temp_path(), without committing (renderer/util/output_transaction.h).
void write_map_png(AtomicOutput& output, int size, const std::vector<std::uint8_t>& rgb,
                   const std::string& description);

}  // namespace ochre
