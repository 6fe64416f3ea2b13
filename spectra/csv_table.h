#pragma once
// CsvTable: a numeric table of spectral data read from CSV text, for the embedded tables and for
// users' files alike.
//
// Format: any number of comment lines starting with '#' (and blank lines), then one header line
// of column names, then numeric rows separated by commas. The header is optional: when the first
// non-comment line is entirely numeric it is taken as data and the columns have no names. The
// first column is the wavelength in nm and must be strictly increasing.
//
// Every error is a std::runtime_error whose message starts with "FILE:LINE: " (or "FILE: " when
// no single line is at fault): non-numeric value, NaN or infinite value, wrong column count,
// wavelengths not strictly increasing, fewer than 2 data rows, unknown column. A file that is
// missing, not a regular file or larger than 64 MiB throws InputError (spectra/input_file.h).
//
//   CsvTable::parse(text, source_name) -> CsvTable   (source_name is used in error messages)
//   CsvTable::load(path) -> CsvTable
//   table.column("n"), table.column(1), table.column_index("n"), table.wavelengths()

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ochre {

class CsvTable {
 public:
  static CsvTable parse(std::string_view text, std::string source_name);
  static CsvTable load(const std::filesystem::path& path);

  const std::string& source() const { return source_; }
  // Column names (empty when the file has no header line).
  const std::vector<std::string>& header() const { return header_; }
  std::size_t column_count() const { return columns_.size(); }
  std::size_t row_count() const { return columns_.empty() ? 0 : columns_[0].size(); }

  // Index of the column with this header name; throws "FILE: no column 'name' (columns: ...)".
  std::size_t column_index(std::string_view name) const;
  // Column by index (throws when out of range) or by header name.
  const std::vector<double>& column(std::size_t index) const;
  const std::vector<double>& column(std::string_view name) const;
  const std::vector<double>& wavelengths() const { return columns_.at(0); }

 private:
  CsvTable() = default;

  std::string source_;
  std::vector<std::string> header_;
  std::vector<std::vector<double>> columns_;
};

}  // namespace ochre
