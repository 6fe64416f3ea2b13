// CSV parsing for spectral tables (see csv_table.h).

#include "spectra/csv_table.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

// The number in a cell, or nothing when the cell is not entirely a number.
std::optional<double> parse_number(std::string_view cell) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  if (cell.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (ec != std::errc() || end != cell.data() + cell.size()) return std::nullopt;
  return value;
}

bool all_numeric(const std::vector<std::string_view>& cells) {
  for (auto cell : cells)
    if (!parse_number(cell)) return false;
  return true;
}

[[noreturn]] void fail(const std::string& source, int line, const std::string& message) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + message);
}

}  // namespace

CsvTable CsvTable::parse(std::string_view text, std::string source_name) {
  CsvTable table;
  table.source_ = std::move(source_name);
  const std::string& src = table.source_;

  bool header_seen = false;
  int line_number = 0;
  int previous_row_line = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto newline = text.find('\n', pos);
    const std::string_view raw =
        text.substr(pos, newline == std::string_view::npos ? std::string_view::npos : newline - pos);
    pos = newline == std::string_view::npos ? text.size() : newline + 1;
    ++line_number;

    const std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    const auto cells = split_cells(line);

    if (!header_seen) {
      header_seen = true;
      if (cells.size() < 2)
        fail(src, line_number,
             "expected at least 2 columns (wavelength and values), found " + std::to_string(cells.size()));
      table.columns_.resize(cells.size());
      if (!all_numeric(cells)) {
        for (auto cell : cells) table.header_.emplace_back(cell);
        continue;
      }
    }

    if (cells.size() != table.columns_.size())
      fail(src, line_number,
           "expected " + std::to_string(table.columns_.size()) + " columns, found " +
               std::to_string(cells.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto value = parse_number(cells[c]);
      if (!value)
        fail(src, line_number,
             "non-numeric value '" + std::string(cells[c]) + "' in column " + std::to_string(c + 1));
      if (std::isnan(*value)) fail(src, line_number, "NaN value in column " + std::to_string(c + 1));
      if (!std::isfinite(*value)) fail(src, line_number, "infinite value in column " + std::to_string(c + 1));
      table.columns_[c].push_back(*value);
    }
    const auto& lambda = table.columns_[0];
    if (lambda.size() >= 2 && !(lambda[lambda.size() - 1] > lambda[lambda.size() - 2])) {
      std::ostringstream msg;
      msg << "wavelengths must be strictly increasing (" << lambda[lambda.size() - 1] << " after "
          << lambda[lambda.size() - 2] << " on line " << previous_row_line << ")";
      fail(src, line_number, msg.str());
    }
    previous_row_line = line_number;
  }

  if (table.row_count() < 2)
    throw std::runtime_error(src + ": fewer than 2 data rows (found " + std::to_string(table.row_count()) +
                             ")");
  return table;
}

CsvTable CsvTable::load(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError(path.string() + ": cannot open file (missing or unreadable)");
  return parse(read_input_file(path, kCsvFileInput), path.string());
}

std::size_t CsvTable::column_index(std::string_view name) const {
  for (std::size_t i = 0; i < header_.size(); ++i)
    if (header_[i] == name) return i;
  std::string known;
  for (const auto& h : header_) known += (known.empty() ? "" : ", ") + h;
  throw std::runtime_error(source_ + ": no column '" + std::string(name) + "' (columns: " +
                           (known.empty() ? "none named, the file has no header" : known) + ")");
}

const std::vector<double>& CsvTable::column(std::size_t index) const {
  if (index >= columns_.size())
    throw std::runtime_error(source_ + ": no column " + std::to_string(index) + " (the table has " +
                             std::to_string(columns_.size()) + " columns, numbered from 0)");
  return columns_[index];
}

const std::vector<double>& CsvTable::column(std::string_view name) const {
  return columns_[column_index(name)];
}

}  // namespace ochre
