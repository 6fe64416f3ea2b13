#include "tools/cli/csv_columns.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <memory>

#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

std::string trim(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  size_t start = 0;
  for (;;) {
    const size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

// Position of each asked-for column in the header.
std::vector<size_t> column_positions(const std::vector<std::string>& header,
                                     std::span<const char* const> columns, const std::string& where) {
  std::vector<size_t> positions;
  for (const char* column : columns) {
    size_t found = header.size();
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == column) found = i;
    if (found == header.size())
      throw InputError(
          fmt::format("{}: header: missing column '{}' (need {})", where, column, fmt::join(columns, ",")));
    positions.push_back(found);
  }
  for (size_t i = 0; i < header.size(); ++i) {
    bool known = false;
    for (const char* column : columns) known = known || header[i] == column;
    if (!known) throw InputError(fmt::format("{}: header: unknown column '{}'", where, header[i]));
    for (size_t j = 0; j < i; ++j)
      if (header[j] == header[i])
        throw InputError(fmt::format("{}: header: column '{}' appears twice", where, header[i]));
  }
  return positions;
}

}  // namespace

std::optional<double> finite_number(const std::string& text) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

CsvColumns read_csv_columns(const std::filesystem::path& file, std::span<const char* const> columns) {
  std::error_code error;
  if (!std::filesystem::exists(file, error))
    throw InputError(fmt::format("{}: cannot open input file", file.string()));
  InputFile input = InputFile::open(file, kCsvFileInput);
  const std::unique_ptr<std::istream> in = input.stream();
  CsvColumns table;
  std::vector<size_t> positions;
  std::string line;
  for (int number = 1; std::getline(*in, line); ++number) {
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const std::string where = fmt::format("{}: line {}", file.string(), number);
    std::vector<std::string> fields = split_fields(content);
    if (table.header.empty()) {
      table.header = fields;
      positions = column_positions(table.header, columns, where);
      continue;
    }
    if (fields.size() != table.header.size())
      throw InputError(fmt::format("{}: {} fields, expected {}", where, fields.size(), table.header.size()));
    CsvRecord record;
    record.line = number;
    for (size_t c = 0; c < columns.size(); ++c) {
      const std::string& text = fields[positions[c]];
      const std::optional<double> value = finite_number(text);
      if (!value)
        throw InputError(fmt::format("{}: column {}: '{}' is not a finite number", where, columns[c], text));
      record.values.push_back(*value);
    }
    record.fields = std::move(fields);
    table.records.push_back(std::move(record));
  }
  if (table.header.empty())
    throw InputError(fmt::format("{}: empty file (expected a header line)", file.string()));
  return table;
}

std::string table_number(double x) {
  return fmt::format("{:.9g}", x);
}

}  // namespace ochre
