#include "cli/file_test_support.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "renderer/image/display_image.h"

namespace ochre::test {

namespace fs = std::filesystem;

std::string minimal_scene(const std::string& materials, const std::string& shapes, const std::string& lights,
                          const std::string& extra) {
  return fmt::format(
      R"({{"film": {{"resolution": [8, 8]}}, "integrator": {{"spp": 1}}, {}{}, {}, {}}})",
      extra.empty() ? "" : extra + ", ",
      materials.empty() ? R"("materials": {"grey": {"type": "lambert", "color": 0.5}})" : materials,
      shapes.empty() ? R"("shapes": [{"type": "plane", "material": "grey"}])" : shapes,
      lights.empty() ? R"("lights": [{"type": "environment", "radiance": 1}])" : lights);
}

void make_fifo(const fs::path& path) {
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
}

void make_sparse_file(const fs::path& path, std::uintmax_t bytes) {
  std::ofstream(path).close();
  fs::resize_file(path, bytes);
}

void write_png(const fs::path& path, int width, int height) {
  std::vector<std::uint8_t> pixels(static_cast<size_t>(width) * height * 3);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 7);
  write_rgb8(path, "png", width, height, pixels, "test texture");
}

FileSnapshot snapshot(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return {bytes.str(), fs::last_write_time(path)};
}

void write_old_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  fs::last_write_time(path, fs::file_time_type::clock::now() - std::chrono::hours(1));
}

std::vector<std::string> temporaries_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos) names.push_back(name);
  }
  return names;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace ochre::test
