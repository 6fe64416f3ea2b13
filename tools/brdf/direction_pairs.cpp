#include "tools/brdf/direction_pairs.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "spectra/input_error.h"
#include "tools/cli/csv_columns.h"

namespace ochre {

namespace {

constexpr std::array<const char*, 7> kColumns = {"wi_x", "wi_y", "wi_z", "wo_x", "wo_y", "wo_z", "lambda_nm"};

Vec3 unit_direction(double x, double y, double z, const char* name, const std::string& where) {
  const double norm = std::sqrt(x * x + y * y + z * z);
  if (!(norm > 0.0)) throw InputError(fmt::format("{}: {} is the zero vector", where, name));
  return {static_cast<float>(x / norm), static_cast<float>(y / norm), static_cast<float>(z / norm)};
}

}  // namespace

DirectionPairTable read_direction_pairs(const std::filesystem::path& file) {
  CsvColumns csv = read_csv_columns(file, kColumns);
  DirectionPairTable table;
  table.header = std::move(csv.header);
  for (CsvRecord& record : csv.records) {
    const std::string where = fmt::format("{}: line {}", file.string(), record.line);
    const std::vector<double>& v = record.values;
    DirectionPair pair;
    pair.wi = unit_direction(v[0], v[1], v[2], "wi", where);
    pair.wo = unit_direction(v[3], v[4], v[5], "wo", where);
    pair.lambda_nm = static_cast<float>(v[6]);
    pair.line = record.line;
    pair.fields = std::move(record.fields);
    table.rows.push_back(std::move(pair));
  }
  return table;
}

}  // namespace ochre
