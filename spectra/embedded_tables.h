#pragma once
// Parsed access to the CSV tables embedded in the library (spectra/data/*.csv, see
// embedded_data.h). Each table is parsed once, on first use, and cached for the program's life.
//
//   embedded_table("cie1931_2deg_1nm.csv") -> const CsvTable&   (throws std::runtime_error with
//                                             the list of embedded files for an unknown name)

#include <string_view>

#include "spectra/csv_table.h"

namespace ochre {

const CsvTable& embedded_table(std::string_view file_name);

}  // namespace ochre
