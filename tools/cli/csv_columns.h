#pragma once
// The tools' CSV inputs of named numeric columns (ochre-brdf's direction pairs, ochre-fit's measurements):
// blank lines and lines starting with '#' are skipped; the first other line is the header naming the
// columns (any order); every following line is one record with as many fields as the header. Each record
// keeps its fields as written (to be repeated in an output) and the numbers of the asked-for columns.

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ochre {

struct CsvRecord {
  int line = 0;                     // in the file, from 1
  std::vector<std::string> fields;  // as written, in the header's order
  std::vector<double> values;       // the asked-for columns, in the order they were asked for
};

struct CsvColumns {
  std::vector<std::string> header;
  std::vector<CsvRecord> records;
};

// Throws InputError "FILE: cannot open input file", "FILE: empty file (expected a header line)",
// "FILE: line N: header: missing column 'x' (need a,b,c)" / "unknown column 'x'" / "column 'x' appears
// twice", "FILE: line N: K fields, expected M", "FILE: line N: column x: 'text' is not a finite number".
CsvColumns read_csv_columns(const std::filesystem::path& file, std::span<const char* const> columns);

// The number `text` spells (as std::stod reads it, up to its last character), when it is finite.
std::optional<double> finite_number(const std::string& text);

// `x` as the tools write numbers in their tables (CSV and text): nine significant digits, enough for a
// float to read back exactly.
std::string table_number(double x);

}  // namespace ochre
