// The printed values of Tables 1-3 of Saint-Pierre, Chavel, Simonot and Hebert, JOSA A 36(11), C51
// (2019), copied as printed (the tables of the HAL version hal-02353266).
#include "tools/vgroove/vgroove_printed_tables.h"

namespace ochre {

namespace {

// Table 1 - Bi-hemispherical reflectance at 550 nm (in %).
constexpr PrintedRow kTable1[] = {
    {"Black glass", {0.9, 1.6, 3.5, 5.5, 7.3, 8.6}},  {"Silicon", {11.0, 16.6, 26.4, 34.0, 36.8, 37.3}},
    {"Gold", {66.3, 72.9, 80.0, 83.6, 85.1, 85.4}},   {"Silver", {89.7, 92.1, 94.4, 95.6, 96.0, 96.1}},
    {"Copper", {33.9, 42.8, 54.4, 61.2, 63.9, 64.6}}, {"Aluminum", {77.1, 82.2, 87.4, 90.2, 91.0, 90.9}},
};

// Table 2 - CIE 1994 Delta E values between colors corresponding to spectral reflectances predicted by
// different models (a: rigorous vs 1st approximate, b: rigorous vs 2nd approximate).
constexpr PrintedRow kTable2[] = {
    {"Black glass", {0.28, 1.01, 1.02, 0.24, 0.37, 0.00}},  {"Gold", {0.39, 0.55, 0.43, 0.13, 0.15, 0.00}},
    {"Copper", {0.52, 0.53, 0.41, 0.56, 0.62, 0.00}},       {"Silicon", {2.50, 2.78, 2.21, 0.44, 0.71, 0.00}},
    {"Silicon (sp)", {6.16, 4.62, 2.72, 1.19, 1.45, 0.00}},
};

// Table 3 - Bi-hemispherical reflectance (in %) at 550 nm of a V-cavity made of silver; rows: number
// of reflections taken into account (1-4), columns: alpha = 45, 60, 90 degrees; 0 = not printed.
constexpr double kTable3[kPaperTable3MaxLimit][3] = {
    {13.4, 24.3, 54.7}, {39.0, 66.7, 94.4}, {71.3, 92.1, 0.0}, {89.7, 0.0, 0.0}};

}  // namespace

std::span<const PrintedRow> printed_table1() {
  return kTable1;
}

std::span<const PrintedRow> printed_table2() {
  return kTable2;
}

std::optional<double> printed_table3(int limit, int alpha_index) {
  if (limit < 1 || limit > kPaperTable3MaxLimit || alpha_index < 0 || alpha_index > 2) return std::nullopt;
  const double v = kTable3[limit - 1][alpha_index];
  if (v == 0.0) return std::nullopt;
  return v;
}

}  // namespace ochre
