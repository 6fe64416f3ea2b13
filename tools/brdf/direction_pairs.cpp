#include "tools/brdf/direction_pairs.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <memory>

#include "renderer/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

constexpr std::array<const char*, 7> kColumns = {"wi_x", "wi_y", "wi_z", "wo_x", "wo_y", "wo_z", "lambda_nm"};

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

// Position of each of kColumns in the header.
std::array<size_t, kColumns.size()> column_positions(const std::vector<std::string>& header,
                                                     const std::string& where) {
  std::array<size_t, kColumns.size()> positions{};
  for (size_t c = 0; c < kColumns.size(); ++c) {
    size_t found = header.size();
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == kColumns[c]) found = i;
    if (found == header.size())
      throw InputError(
          fmt::format("{}: header: missing column '{}' (need wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm)", where,
                      kColumns[c]));
    positions[c] = found;
  }
  for (const std::string& name : header) {
    bool known = false;
    for (const char* column : kColumns) known = known || name == column;
    if (!known) throw InputError(fmt::format("{}: header: unknown column '{}'", where, name));
  }
  return positions;
}

double parse_number(const std::string& text, const std::string& column, const std::string& where) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value))
    throw InputError(fmt::format("{}: column {}: '{}' is not a finite number", where, column, text));
  return value;
}

Vec3 unit_direction(double x, double y, double z, const char* name, const std::string& where) {
  const double norm = std::sqrt(x * x + y * y + z * z);
  if (!(norm > 0.0)) throw InputError(fmt::format("{}: {} is the zero vector", where, name));
  return {static_cast<float>(x / norm), static_cast<float>(y / norm), static_cast<float>(z / norm)};
}

}  // namespace

DirectionPairTable read_direction_pairs(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::exists(file, error))
    throw InputError(fmt::format("{}: cannot open input file", file.string()));
  InputFile input = InputFile::open(file, kCsvFileInput);
  const std::unique_ptr<std::istream> in = input.stream();
  DirectionPairTable table;
  std::array<size_t, kColumns.size()> positions{};
  std::string line;
  for (int number = 1; std::getline(*in, line); ++number) {
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const std::string where = fmt::format("{}: line {}", file.string(), number);
    std::vector<std::string> fields = split_fields(content);
    if (table.header.empty()) {
      table.header = fields;
      positions = column_positions(table.header, where);
      continue;
    }
    if (fields.size() != table.header.size())
      throw InputError(fmt::format("{}: {} fields, expected {}", where, fields.size(), table.header.size()));
    std::array<double, kColumns.size()> v{};
    for (size_t c = 0; c < kColumns.size(); ++c)
      v[c] = parse_number(fields[positions[c]], kColumns[c], where);
    DirectionPair pair;
    pair.wi = unit_direction(v[0], v[1], v[2], "wi", where);
    pair.wo = unit_direction(v[3], v[4], v[5], "wo", where);
    pair.lambda_nm = static_cast<float>(v[6]);
    pair.line = number;
    pair.fields = std::move(fields);
    table.rows.push_back(std::move(pair));
  }
  if (table.header.empty())
    throw InputError(fmt::format("{}: empty file (expected a header line)", file.string()));
  return table;
}

}  // namespace ochre
