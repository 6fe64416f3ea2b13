#pragma once
// Small files for tests: write a text file, read any file back whole.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ochre::test {

// Writes `text` to `path` (creating directories), directly: a test's own file, not an output of ochre
// (those go through ochre::write_text_file, renderer/util/atomic_file.h).
inline void write_text(const std::filesystem::path& path, const std::string& text) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// The whole file as bytes (a PNG's signature, a CSV, a scene); empty when it cannot be opened.
inline std::string read_file_contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace ochre::test
