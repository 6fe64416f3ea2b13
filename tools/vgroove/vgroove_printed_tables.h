#pragma once
// The values printed in Tables 1-3 of Saint-Pierre, Chavel, Simonot and Hebert, "Angular reflectance
// model for ridged specular surfaces, with comprehensive calculation of inter-reflections and
// polarization", JOSA A 36(11), C51 (2019). ochre-vgroove tables prints them beside its own values.

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace ochre {

// The dihedral angles (degrees) of the columns of Tables 1 and 2.
inline constexpr std::array<double, 6> kPaperTableAlphas{45, 60, 90, 120, 150, 180};

struct PrintedRow {
  std::string_view name;
  std::array<double, 6> values;  // one per kPaperTableAlphas
};

// Table 1: bi-hemispherical reflectance (%) at 550 nm, rigorous model. Rows: black glass, silicon,
// gold, silver, copper, aluminium.
std::span<const PrintedRow> printed_table1();

// Table 2: CIE 1994 Delta E between the colours of spectral bi-hemispherical reflectances. Rows:
// black glass, gold, copper, silicon (rigorous vs 1st approximate = unpolarized), silicon (rigorous vs
// 2nd approximate = s/p).
std::span<const PrintedRow> printed_table2();

// Table 3: bi-hemispherical reflectance (%) at 550 nm of silver (n = 0.1249 + 3.3391i), rays with more
// than `limit` reflections discarded, for alpha = 45, 60, 90 degrees. Empty where the paper prints
// nothing (the limit is above the most reflections any ray makes).
inline constexpr std::array<double, 3> kPaperTable3Alphas{45, 60, 90};
std::optional<double> printed_table3(int limit, int alpha_index);
inline constexpr int kPaperTable3MaxLimit = 4;

}  // namespace ochre
