#pragma once
// Small text files for tests: write one, read one back whole.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ochre::test {

inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace ochre::test
