#pragma once
// Row-and-column output of ochre-vgroove: CSV (header line, one line per row, fields joined by commas)
// or text aligned for reading (numbers right-aligned, other fields left-aligned).

#include <string>
#include <vector>

namespace ochre {

struct TextTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  std::string csv() const;
  std::string aligned() const;
};

}  // namespace ochre
