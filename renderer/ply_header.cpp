#include "renderer/ply_header.h"

#include <fmt/format.h>

#include <fstream>
#include <string>

#include "renderer/input_error.h"

namespace ochre {

namespace {

// The line without the '\r' of a CRLF file.
std::string without_cr(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

}  // namespace

void check_ply_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || without_cr(line) != "ply") return;
  while (std::getline(in, line))
    if (without_cr(line).starts_with("end_header")) return;
  throw InputError(fmt::format("{}: malformed PLY header: no end_header line", file.string()));
}

}  // namespace ochre
