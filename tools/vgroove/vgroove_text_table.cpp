#include "tools/vgroove/vgroove_text_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

namespace ochre {

namespace {

bool is_number(const std::string& s) {
  double value = 0.0;
  const char* begin = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(begin, s.data() + s.size(), value);
  return !s.empty() && error == std::errc() && end == s.data() + s.size();
}

std::string joined(const std::vector<std::string>& fields, const std::vector<size_t>* widths) {
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    if (!widths) {
      line += (i ? "," : "") + fields[i];
      continue;
    }
    const size_t w = (*widths)[i];
    line += (i ? "  " : "") + (is_number(fields[i]) ? fmt::format("{:>{}}", fields[i], w)
                                                    : fmt::format("{:<{}}", fields[i], w));
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line + "\n";
}

}  // namespace

std::string TextTable::csv() const {
  std::string text = joined(header, nullptr);
  for (const auto& row : rows) text += joined(row, nullptr);
  return text;
}

std::string TextTable::aligned() const {
  std::vector<size_t> widths(header.size(), 0);
  auto widen = [&](const std::vector<std::string>& fields) {
    for (size_t i = 0; i < fields.size() && i < widths.size(); ++i)
      widths[i] = std::max(widths[i], fields[i].size());
  };
  widen(header);
  for (const auto& row : rows) widen(row);
  std::string text = joined(header, &widths);
  for (const auto& row : rows) text += joined(row, &widths);
  return text;
}

}  // namespace ochre
