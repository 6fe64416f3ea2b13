// ochre-vgroove end to end (docs/tools.md): exact CSV headers and row counts, values against the V-groove
// library and closed forms (ideal mirrors reflect everything; the flat black glass is the hemispherical
// Fresnel average 0.0918), the paper's tables beside their printed values, the maps' size, colour and
// reflection counts, the Brewster dip of the lightness profile, and every bad-input path (exit code 2,
// a message naming the option, no output file).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "cli/vgroove_library_values.h"
#include "renderer/image/display_image.h"
#include "spectra/cie.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::ochre_vgroove_test {
namespace {

const char* kTool = "ochre-vgroove";

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> fields;
  std::stringstream s(text);
  std::string field;
  while (std::getline(s, field, separator)) fields.push_back(field);
  return fields;
}

struct Csv {
  std::string header;
  std::vector<std::vector<std::string>> rows;
};

Csv parse_csv(const std::string& text) {
  Csv csv;
  std::vector<std::string> lines = split(text, '\n');
  if (lines.empty()) return csv;
  csv.header = lines[0];
  for (size_t i = 1; i < lines.size(); ++i)
    if (!lines[i].empty()) csv.rows.push_back(split(lines[i], ','));
  return csv;
}

// Runs the tool expecting success and returns its standard output as CSV.
Csv run_csv(const std::string& args, const std::filesystem::path& dir = {}) {
  const CommandResult r = run_tool(kTool, args, dir, /*stdout_only=*/true);
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.output;
  return parse_csv(r.output);
}

bool have_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0;
}

const FacetSpec kGlass{1.5, 0.0, false};
const FacetSpec kPaperSilver{0.1249, 3.3391, false};
const FacetSpec kMirror{1.0, 0.0, true};

// ---------------------------------------------------------------------------------------------------
// bihemispherical

TEST(OchreVGroove, BihemisphericalHeaderRowsAndTheFlatGlassFresnelAverage) {
  const Csv csv =
      run_csv("bihemispherical --material glass --wavelength 550 --alpha 45,90,180 --model rigorous --csv");
  EXPECT_EQ(csv.header, "material,alpha_deg,model,wavelength_nm,R");
  ASSERT_EQ(csv.rows.size(), 3u);
  const char* alphas[] = {"45", "90", "180"};
  for (size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(csv.rows[i].size(), 5u);
    EXPECT_EQ(csv.rows[i][0], "glass");
    EXPECT_EQ(csv.rows[i][1], alphas[i]);
    EXPECT_EQ(csv.rows[i][2], "rigorous");
    EXPECT_EQ(csv.rows[i][3], "550");
    EXPECT_NEAR(std::stod(csv.rows[i][4]), library_bihemispherical(kGlass, std::stod(alphas[i]), "rigorous"),
                1e-6);
  }
  // The flat surface: 2 int_0^1 R_F(mu) mu dmu = 0.0918 for n = 1.5.
  EXPECT_NEAR(std::stod(csv.rows[2][4]), 0.0918, 5e-4);
}

TEST(OchreVGroove, BihemisphericalOfIdealMirrorsIsOneForEveryAngleAndModel) {
  const Csv csv = run_csv(
      "bihemispherical --material mirror --alpha 10,45,60,90,133,180 --model "
      "rigorous,unpolarized,sp,paper_literal "
      "--quadrature 16 --csv");
  ASSERT_EQ(csv.rows.size(), 6u * 4u);
  for (const auto& row : csv.rows) {
    EXPECT_EQ(row[0], "mirror");
    EXPECT_NEAR(std::stod(row[4]), 1.0, 1e-6) << row[1] << " " << row[2];
  }
  // Rows: alpha-major, then model in the order given.
  EXPECT_EQ(csv.rows[0][2], "rigorous");
  EXPECT_EQ(csv.rows[3][2], "paper_literal");
  EXPECT_EQ(csv.rows[4][1], "45");
}

TEST(OchreVGroove, BihemisphericalSeveralWavelengthsUseTheBuiltInOpticalData) {
  const Csv csv =
      run_csv("bihemispherical --material au --wavelength 450,550,650 --alpha 60 --model unpolarized --csv");
  ASSERT_EQ(csv.rows.size(), 3u);
  const double lambdas[] = {450, 550, 650};
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(csv.rows[i][0], "Au") << "canonical spelling";
    EXPECT_EQ(std::stod(csv.rows[i][3]), lambdas[i]);
    EXPECT_NEAR(std::stod(csv.rows[i][4]),
                library_bihemispherical(tabulated_facet("Au", lambdas[i]), 60, "unpolarized"), 1e-6);
  }
  // Gold reflects red better than blue.
  EXPECT_GT(std::stod(csv.rows[2][4]), std::stod(csv.rows[0][4]) + 0.2);
}

TEST(OchreVGroove, BihemisphericalTable3RowsWithLimitedReflections) {
  // The paper's silver; rays with more than K reflections discarded.
  for (int limit : {1, 2, 3}) {
    const Csv csv = run_csv("bihemispherical --material paper-silver --alpha 45,60,90 --max-reflections " +
                            std::to_string(limit) + " --csv");
    ASSERT_EQ(csv.rows.size(), 3u);
    const double alphas[] = {45, 60, 90};
    for (size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(std::stod(csv.rows[i][4]),
                  library_bihemispherical(kPaperSilver, alphas[i], "rigorous", limit), 1e-6)
          << "alpha " << alphas[i] << " limit " << limit;
  }
  // At 90 degrees, 58.6 % of the flux reflects exactly once: with ideal mirrors the 1-reflection row is it.
  const Csv once = run_csv("bihemispherical --material mirror --alpha 90 --max-reflections 1 --csv");
  EXPECT_NEAR(std::stod(once.rows[0][4]), 0.586, 0.001);
}

TEST(OchreVGroove, BihemisphericalExplicitIndexEqualsTheNamedMaterial) {
  const Csv named = run_csv("bihemispherical --material glass --alpha 75 --csv");
  const Csv explicit_index = run_csv("bihemispherical --ior 1.5,0 --alpha 75 --csv");
  ASSERT_EQ(explicit_index.rows.size(), 1u);
  EXPECT_EQ(explicit_index.rows[0][0], "n=1.5 k=0");
  EXPECT_EQ(explicit_index.rows[0][4], named.rows[0][4]);
}

TEST(OchreVGroove, BihemisphericalAlignedTextWithoutCsv) {
  const CommandResult r = run_tool(kTool, "bihemispherical --material glass --alpha 180", {}, true);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find(','), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("material  alpha_deg  model     wavelength_nm  R"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0.0917"), std::string::npos) << r.output;
}

// ---------------------------------------------------------------------------------------------------
// directional

TEST(OchreVGroove, DirectionalHeaderRowsValuesAndReflectionCounts) {
  const Csv csv = run_csv(
      "directional --material Si --wavelength 550 --alpha 45 --theta 0,30,61 --phi 0,90 --model rigorous "
      "--csv");
  EXPECT_EQ(csv.header, "theta_deg,phi_deg,R,max_reflections");
  ASSERT_EQ(csv.rows.size(), 6u);
  const FacetSpec si = tabulated_facet("Si", 550);
  size_t i = 0;
  for (double theta : {0.0, 30.0, 61.0})
    for (double phi : {0.0, 90.0}) {
      const LibraryDirectional want = library_directional(si, 45, theta, phi, "rigorous");
      ASSERT_EQ(csv.rows[i].size(), 4u);
      EXPECT_EQ(std::stod(csv.rows[i][0]), theta);
      EXPECT_EQ(std::stod(csv.rows[i][1]), phi);
      EXPECT_NEAR(std::stod(csv.rows[i][2]), want.reflectance, 1e-6) << theta << " " << phi;
      EXPECT_EQ(std::stoi(csv.rows[i][3]), want.max_reflections);
      ++i;
    }
  // Normal incidence into a 45 degree groove: up to ceil(180 / 45) = 4 reflections.
  EXPECT_EQ(csv.rows[0][3], "4");
  // Along the grooves near Brewster's angle the rigorous reflectance nearly vanishes (Fig 9b).
  EXPECT_LT(std::stod(csv.rows[5][2]), 2e-3);
}

TEST(OchreVGroove, DirectionalReflectionCountsOfSimpleGrooves) {
  // A right-angled groove at normal incidence is a corner reflector: two reflections; a flat surface: one.
  EXPECT_EQ(run_csv("directional --material glass --alpha 90 --theta 0 --phi 0 --csv").rows[0][3], "2");
  EXPECT_EQ(run_csv("directional --material glass --alpha 180 --theta 0,45,89 --phi 30 --csv").rows[2][3],
            "1");
  // Flat glass at normal incidence: ((n - 1) / (n + 1))^2 = 0.04.
  EXPECT_NEAR(
      std::stod(run_csv("directional --material glass --alpha 180 --theta 0 --phi 0 --csv").rows[0][2]), 0.04,
      1e-6);
  // Models differ along the grooves, and mirrors reflect everything.
  const Csv mirror =
      run_csv("directional --material mirror --alpha 30 --theta 10,50,85 --phi 0,45,90 --model sp --csv");
  ASSERT_EQ(mirror.rows.size(), 9u);
  for (const auto& row : mirror.rows) EXPECT_EQ(row[2], "1.000000");
}

// ---------------------------------------------------------------------------------------------------
// tables

TEST(OchreVGroove, TablesCsvHoldsOursPrintedAndTheirDifference) {
  const Csv csv = run_csv("tables --csv");
  EXPECT_EQ(csv.header, "table,row,alpha_deg,ours,printed,difference");
  std::map<std::string, int> per_table;
  std::map<std::string, std::vector<std::string>> by_key;
  for (const auto& row : csv.rows) {
    ASSERT_EQ(row.size(), 6u);
    ++per_table[row[0]];
    by_key[row[0] + "|" + row[1] + "|" + row[2]] = row;
    // difference = ours - printed, to the printed decimals.
    EXPECT_NEAR(std::stod(row[5]), std::stod(row[3]) - std::stod(row[4]), 0.0011) << row[1] << " " << row[2];
  }
  EXPECT_EQ(per_table["1"], 36);
  EXPECT_EQ(per_table["2"], 30);
  EXPECT_EQ(per_table["3"], 9);
  // Printed values (Saint-Pierre et al. 2019) as printed.
  EXPECT_EQ(by_key["1|Black glass|180"][4], "8.6");
  EXPECT_EQ(by_key["1|Silicon|45"][4], "11.0");
  EXPECT_EQ(by_key["1|Aluminum|150"][4], "91.0");
  EXPECT_EQ(by_key["2|Silicon (sp)|45"][4], "6.16");
  EXPECT_EQ(by_key["2|Gold|180"][4], "0.00");
  EXPECT_EQ(by_key["3|1 reflection|90"][4], "54.7");
  EXPECT_EQ(by_key["3|4 reflections|45"][4], "89.7");
  // Ours: the flat glass is the exact Fresnel average; Table 3 against the library; no model
  // difference on a flat surface.
  EXPECT_EQ(by_key["1|Black glass|180"][3], "9.18");
  EXPECT_EQ(by_key["1|Black glass|180"][5], "+0.58");
  EXPECT_NEAR(std::stod(by_key["3|2 reflections|60"][3]),
              100.0 * library_bihemispherical(kPaperSilver, 60, "rigorous", 2), 0.006);
  EXPECT_NEAR(std::stod(by_key["1|Silver|90"][3]),
              100.0 * library_bihemispherical(kPaperSilver, 90, "rigorous"), 0.006);
  for (const char* row : {"Black glass", "Gold", "Copper", "Silicon", "Silicon (sp)"})
    EXPECT_EQ(by_key[std::string("2|") + row + "|180"][3], "0.000") << row;
  // Silicon is where the models differ most, and the s/p model more than the unpolarized one at 45 deg.
  EXPECT_GT(std::stod(by_key["2|Silicon (sp)|45"][3]), std::stod(by_key["2|Silicon|45"][3]));
  EXPECT_GT(std::stod(by_key["2|Silicon|45"][3]), std::stod(by_key["2|Gold|45"][3]));
}

TEST(OchreVGroove, TablesTextLaysOutEachTableWithOursPrintedAndDifference) {
  // Coarse quadratures: the layout is under test here, the values in the CSV test.
  const CommandResult r = run_tool(kTool, "tables --quadrature 24 --spectral-quadrature 8", {}, true);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* expected : {"Table 1:", "Table 2:", "Table 3:", "Black glass  ours", "printed",
                               "difference", "1 reflection", "4 reflections", "Silicon (sp)"})
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  // The printed Table 1 row of aluminium, aligned.
  EXPECT_NE(r.output.find("77.1   82.2   87.4   90.2   91.0   90.9"), std::string::npos) << r.output;
}

// ---------------------------------------------------------------------------------------------------
// maps

// The sRGB 8-bit colour of a reflectance spectrum at 380..730 nm (10 nm) under D65, computed here
// independently of the tool: XYZ relative to the white diffuser, scaled to the sRGB white and through
// the IEC 61966-2-1 matrix.
std::array<int, 3> expected_srgb(const std::vector<double>& reflectance) {
  double xyz[3] = {0, 0, 0}, white[3] = {0, 0, 0};
  for (size_t i = 0; i < reflectance.size(); ++i) {
    const float lambda = 380.0f + 10.0f * static_cast<float>(i);
    const double s = d65()->eval(lambda);
    const double cmf[3] = {cie_x(lambda), cie_y(lambda), cie_z(lambda)};
    for (int c = 0; c < 3; ++c) {
      xyz[c] += reflectance[i] * s * cmf[c];
      white[c] += s * cmf[c];
    }
  }
  const double srgb_white[3] = {0.9505, 1.0, 1.0890};
  double v[3];
  for (int c = 0; c < 3; ++c) v[c] = xyz[c] / white[c] * srgb_white[c];
  const double m[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
  std::array<int, 3> out;
  for (int r = 0; r < 3; ++r) {
    const double linear = std::clamp(m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2], 0.0, 1.0);
    const double encoded = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    out[r] = static_cast<int>(std::lround(255.0 * encoded));
  }
  return out;
}

std::array<int, 3> pixel(const std::vector<std::uint8_t>& rgb, int width, int column, int row) {
  const size_t i = 3 * (static_cast<size_t>(row) * width + column);
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void expect_colour_near(const std::array<int, 3>& got, const std::array<int, 3>& want, int tolerance,
                        const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << what << " channel " << c;
}

TEST(OchreVGroove, MapCentreIsTheColourOfTheReflectanceAtNormalIncidence) {
  const auto dir = scratch_dir();
  const CommandResult r = run_tool(
      kTool, "maps --material Au --alpha 60 --model rigorous --size 33 -o au.png --counts counts.png", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int width = 0, height = 0;
  const std::vector<std::uint8_t> colour = read_png_rgb8(dir / "au.png", width, height);
  EXPECT_EQ(width, 33);
  EXPECT_EQ(height, 33);
  std::vector<double> spectrum;
  for (int lambda = 380; lambda <= 730; lambda += 10)
    spectrum.push_back(library_directional(tabulated_facet("Au", lambda), 60, 0, 0, "rigorous").reflectance);
  expect_colour_near(pixel(colour, width, 16, 16), expected_srgb(spectrum), 2, "centre");
  // Gold: red above blue.
  EXPECT_GT(pixel(colour, width, 16, 16)[0], pixel(colour, width, 16, 16)[2] + 50);
  // Outside the disk (radius sqrt 2 on a square of side 2 sqrt 2): white.
  expect_colour_near(pixel(colour, width, 0, 0), {255, 255, 255}, 0, "corner");
  expect_colour_near(pixel(colour, width, 32, 32), {255, 255, 255}, 0, "corner");

  // Counts: 60 degrees -> 3 reflections at normal incidence (orange), 1 near grazing across the grooves.
  const std::vector<std::uint8_t> counts = read_png_rgb8(dir / "counts.png", width, height);
  EXPECT_EQ(width, 33);
  expect_colour_near(pixel(counts, width, 16, 16), {238, 153, 51}, 0, "3 reflections");
  expect_colour_near(pixel(counts, width, 1, 16), {211, 211, 211}, 0, "1 reflection");
  expect_colour_near(pixel(counts, width, 0, 0), {255, 255, 255}, 0, "outside");
}

TEST(OchreVGroove, MapsOfFlatGlassAndMirrorsAndTheCountPalette) {
  const auto dir = scratch_dir();
  int width = 0, height = 0;
  // Flat glass at normal incidence: R = 0.04 at every wavelength, a grey of sRGB level
  // 255 (1.055 0.04^(1 / 2.4) - 0.055) = 56.
  ASSERT_EQ(run_tool(kTool, "maps --material glass --alpha 180 --size 21 -o glass.png", dir).exit_code, 0);
  const std::vector<std::uint8_t> glass = read_png_rgb8(dir / "glass.png", width, height);
  EXPECT_EQ(width, 21);
  expect_colour_near(pixel(glass, width, 10, 10), {56, 56, 56}, 1, "flat glass");
  // Ideal mirrors: white everywhere in the disk; 45 degrees: 4 reflections at normal incidence (red);
  // an even size has no centre pixel but the same 4 near it.
  ASSERT_EQ(run_tool(kTool, "maps --material mirror --alpha 45 --size 64 -o mirror.png --counts c.png", dir)
                .exit_code,
            0);
  const std::vector<std::uint8_t> mirror = read_png_rgb8(dir / "mirror.png", width, height);
  EXPECT_EQ(width, 64);
  EXPECT_EQ(height, 64);
  for (int row = 0; row < 64; row += 7)
    for (int column = 0; column < 64; column += 7)
      expect_colour_near(pixel(mirror, width, column, row), {255, 255, 255}, 0, "mirror");
  const std::vector<std::uint8_t> counts = read_png_rgb8(dir / "c.png", width, height);
  expect_colour_near(pixel(counts, width, 31, 31), {204, 51, 17}, 0, "4 reflections");
  // 20 degrees: up to 9 reflections near normal incidence, drawn in the "more than 4" colour.
  ASSERT_EQ(run_tool(kTool, "maps --material mirror --alpha 20 --size 9 -o m20.png --counts c20.png", dir)
                .exit_code,
            0);
  const std::vector<std::uint8_t> c20 = read_png_rgb8(dir / "c20.png", width, height);
  expect_colour_near(pixel(c20, width, 4, 4), {119, 51, 136}, 0, "more than 4 reflections");
}

TEST(OchreVGroove, MapsGridFigureOfSeveralAnglesLeavesNoScratchFiles) {
  if (!have_matplotlib()) GTEST_SKIP() << "python3-matplotlib is not installed";
  const auto dir = scratch_dir();
  const CommandResult r = run_tool(
      kTool, "maps --material glass,Au --alpha 60,180 --size 16 -o grid.png --counts grid_counts.png", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name : {"grid.png", "grid_counts.png"}) {
    const std::string png = read_file_contents(dir / name);
    ASSERT_GT(png.size(), 8u) << name;
    EXPECT_EQ(png.substr(1, 3), "PNG") << name;
  }
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"grid.png", "grid_counts.png"}));
}

// ---------------------------------------------------------------------------------------------------
// profile

TEST(OchreVGroove, ProfileHasTheBrewsterDipAlongTheGroovesInTheRigorousModelOnly) {
  const auto dir = scratch_dir();
  const CommandResult r = run_tool(kTool, "profile --material Si --alpha 45 -o profile.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Csv csv = parse_csv(read_file_contents(dir / "profile.csv"));
  EXPECT_EQ(csv.header, "phi_deg,theta_deg,model,L");
  // theta = 0, 0.5, ..., 89.5 for phi = 0 and 90 and three models.
  ASSERT_EQ(csv.rows.size(), 2u * 3u * 180u);
  std::map<std::string, std::map<double, double>> curves;  // "phi|model" -> theta -> L*
  for (const auto& row : csv.rows) {
    ASSERT_EQ(row.size(), 4u);
    curves[row[0] + "|" + row[2]][std::stod(row[1])] = std::stod(row[3]);
  }
  ASSERT_EQ(curves.size(), 6u);
  const auto& rigorous = curves["90|rigorous"];
  const auto lowest = std::min_element(rigorous.begin(), rigorous.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
  EXPECT_NEAR(lowest->first, 61.0, 1.5);
  EXPECT_LT(lowest->second, 2.0);
  EXPECT_GT(curves["90|unpolarized"][lowest->first], 10.0);
  EXPECT_GT(curves["90|sp"][lowest->first], 10.0);
  // Across the grooves every plane of incidence is the same: rigorous = s/p exactly.
  for (const auto& [theta, l] : curves["0|rigorous"]) EXPECT_NEAR(curves["0|sp"][theta], l, 1e-4) << theta;
  // The rigorous and unpolarized models differ at normal incidence (4 reflections).
  EXPECT_GT(std::abs(curves["0|rigorous"][0.0] - curves["0|unpolarized"][0.0]), 1.0);
}

TEST(OchreVGroove, ProfilePlot) {
  if (!have_matplotlib()) GTEST_SKIP() << "python3-matplotlib is not installed";
  const auto dir = scratch_dir();
  const CommandResult r = run_tool(
      kTool, "profile --material Si --alpha 45 --model rigorous,sp --step 5 -o p.csv --png p.png", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(parse_csv(read_file_contents(dir / "p.csv")).rows.size(), 2u * 2u * 18u);
  EXPECT_EQ(read_file_contents(dir / "p.png").substr(1, 3), "PNG");
}

// ---------------------------------------------------------------------------------------------------
// compare

const char* kCompareHeader =
    "material,alpha_deg,theta_deg,phi_deg,exact,explicit,explicit_se,explicit_seconds,analytic,analytic_se,"
    "analytic_seconds,microgroove,microgroove_se,microgroove_seconds";

// Each rendered mean (explicit plate, vgroove plane, microgroove plane) against the exact R of the row.
void expect_renders_match_exact(const std::vector<std::string>& row) {
  const double exact = std::stod(row[4]);
  for (size_t column : {5u, 8u, 11u}) {
    const double value = std::stod(row[column]), se = std::stod(row[column + 1]);
    EXPECT_GT(se, 0.0) << row[0] << " " << row[1] << " " << row[2] << " " << row[3] << " column " << column;
    EXPECT_NEAR(value, exact, 3.0 * se + 1e-3)
        << row[0] << " alpha " << row[1] << " theta " << row[2] << " phi " << row[3] << " column " << column;
    EXPECT_GT(std::stod(row[column + 2]), 0.0) << "seconds";
  }
}

TEST(OchreVGroove, CompareRowsRenderTheExactReflectance) {
  const Csv csv = run_csv(
      "compare --material Si,Au --alpha 45,90 --theta 10,50 --phi 0,90 --spp 8 --resolution 16 --csv");
  EXPECT_EQ(csv.header, kCompareHeader);
  ASSERT_EQ(csv.rows.size(), 16u);
  size_t i = 0;
  for (const char* material : {"Si", "Au"})
    for (double alpha : {45.0, 90.0})
      for (double theta : {10.0, 50.0})
        for (double phi : {0.0, 90.0}) {
          const std::vector<std::string>& row = csv.rows[i++];
          ASSERT_EQ(row.size(), 14u);
          EXPECT_EQ(row[0], material);
          EXPECT_EQ(std::stod(row[1]), alpha);
          EXPECT_EQ(std::stod(row[2]), theta);
          EXPECT_EQ(std::stod(row[3]), phi);
          // The facets: each material's index at 550 nm, constant over wavelength.
          const double exact =
              library_directional(tabulated_facet(material, 550), alpha, theta, phi, "rigorous").reflectance;
          EXPECT_NEAR(std::stod(row[4]), exact, 1e-6 * exact);
          expect_renders_match_exact(row);
        }
}

TEST(OchreVGroove, CompareOfIdealMirrorsIsExactlyOneAndGlassMatches) {
  // Mirror facets reflect every sample's radiance unchanged: each image equals the environment's.
  const Csv mirror =
      run_csv("compare --material mirror --alpha 30 --theta 0,40 --phi 60 --spp 4 --resolution 8 --csv");
  ASSERT_EQ(mirror.rows.size(), 2u);
  for (const auto& row : mirror.rows) {
    EXPECT_EQ(row[4], "1");
    for (size_t column : {5u, 8u, 11u}) EXPECT_EQ(row[column], "1") << column;
  }
  const Csv glass =
      run_csv("compare --material glass --alpha 60 --theta 70 --phi 30 --spp 8 --resolution 16 --csv");
  ASSERT_EQ(glass.rows.size(), 1u);
  EXPECT_NEAR(std::stod(glass.rows[0][4]), library_directional(kGlass, 60, 70, 30, "rigorous").reflectance,
              1e-7);
  expect_renders_match_exact(glass.rows[0]);
}

TEST(OchreVGroove, CompareTextHasTheFacetsTheTableAndTheSummary) {
  const CommandResult r = run_tool(
      kTool, "compare --ior 1.5,0.1 --alpha 90 --theta 30 --phi 0,45 --spp 4 --resolution 8", {}, true);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* expected :
       {"facet indices, constant at every wavelength (each material's at 550 nm): "
        "n=1.5 k=0.1 n = 1.5000, k = "
        "0.1000\n",
        "alpha_deg  theta_deg  phi_deg  exact", "summary over 2 views:", "explicit     max |diff|/SE",
        "analytic     max |diff|/SE", "microgroove  max |diff|/SE", "time explicit/analytic: mean"})
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  EXPECT_EQ(r.output.find("exact,"), std::string::npos) << "not CSV\n" << r.output;
}

TEST(OchreVGroove, CompareKeepsItsScenesInTheSceneDir) {
  const auto dir = scratch_dir();
  std::filesystem::create_directories(dir / "scenes");
  const CommandResult r = run_tool(
      kTool,
      "compare --material Si --alpha 40 --theta 20 --phi 10 --spp 2 --resolution 4 --scene-dir scenes --csv",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "scenes"))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{
                       "Si_alpha40_theta20_phi10_analytic.json", "Si_alpha40_theta20_phi10_explicit.json",
                       "Si_alpha40_theta20_phi10_microgroove.json", "environment.json"}));
  // No Russian roulette, and room for the ceil(180 / 40) = 5 reflections.
  const std::string plate = read_file_contents(dir / "scenes" / "Si_alpha40_theta20_phi10_explicit.json");
  for (const char* expected :
       {R"("type": "groove_plate", "alpha": 40)", R"("max_depth": 7, "rr_depth": 7)",
        R"("type": "conductor", "eta": 4.07)", R"("resolution": [4, 4])", R"("spp": 2)"})
    EXPECT_NE(plate.find(expected), std::string::npos) << expected << "\n" << plate;
  EXPECT_NE(read_file_contents(dir / "scenes" / "Si_alpha40_theta20_phi10_analytic.json")
                .find(R"("type": "vgroove")"),
            std::string::npos);
  EXPECT_NE(read_file_contents(dir / "scenes" / "Si_alpha40_theta20_phi10_microgroove.json")
                .find(R"("type": "microgroove")"),
            std::string::npos);
  // The kept scene renders with ochre itself.
  EXPECT_EQ(run_ochre("render scenes/Si_alpha40_theta20_phi10_explicit.json -o out.exr", dir).exit_code, 0);
}

// ---------------------------------------------------------------------------------------------------
// bad input

struct BadCase {
  std::string args, message;
};

void expect_bad_input(const std::vector<BadCase>& cases) {
  for (const BadCase& c : cases) {
    const auto dir = scratch_dir();
    const CommandResult r = run_tool(kTool, c.args, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << c.args << ": an output file was written";
  }
}

// Unknown names, both or neither of --material and --ior, malformed or unphysical indices.
TEST(OchreVGroove, BadMaterialExitsWithTwoAndNamesTheOption) {
  expect_bad_input({
      {"bihemispherical --material Pt --alpha 45", "--material: unknown material 'Pt'"},
      {"bihemispherical --alpha 45", "give the facet material"},
      {"bihemispherical --material Au --ior 1,2 --alpha 45", "give only one of them"},
      {"bihemispherical --ior 1.5 --alpha 45", "--ior: '1.5' is not n,k"},
      {"bihemispherical --ior -1,0 --alpha 45", "--ior: n = -1 must be positive"},
      {"bihemispherical --ior 1.5,-2 --alpha 45", "--ior: k = -2 must be 0 or more"},
      {"bihemispherical --ior 1.5,x --alpha 45", "--ior: 'x' is not a finite number"},
  });
}

// Malformed lists, non-finite numbers, angles, wavelengths and counts out of range.
TEST(OchreVGroove, BadListsAndRangesExitWithTwoAndNameTheOption) {
  expect_bad_input({
      {"bihemispherical --material glass --alpha 45,,60", "--alpha: empty item in '45,,60'"},
      {"bihemispherical --material glass --alpha 45,abc", "--alpha: 'abc' is not a finite number"},
      {"bihemispherical --material glass --alpha nan", "--alpha: 'nan' is not a finite number"},
      {"bihemispherical --material glass --alpha 0", "--alpha: dihedral angle 0 is outside (0, 180]"},
      {"bihemispherical --material glass --alpha 180.5", "--alpha: dihedral angle 180.5 is outside (0, 180]"},
      {"bihemispherical --material glass --alpha 45 --model fancy", "--model: unknown model 'fancy'"},
      {"bihemispherical --material glass --alpha 45 --wavelength 200", "--wavelength: 200 nm is outside"},
      {"bihemispherical --material glass --alpha 45 --max-reflections -1",
       "--max-reflections: -1 is negative"},
      {"bihemispherical --material glass --alpha 45 --max-reflections two", "--max-reflections"},
      {"bihemispherical --material glass --alpha 45 --quadrature 1", "--quadrature: 1 points"},
      {"directional --material glass --alpha 45 --theta 90 --phi 0",
       "--theta: polar angle 90 is outside [0, 90)"},
      {"directional --material glass --alpha 45 --theta -1 --phi 0", "--theta: polar angle -1 is outside"},
      {"directional --material glass --alpha 45 --theta 10 --phi x", "--phi: 'x' is not a finite number"},
      {"directional --material glass --alpha 45,60 --theta 10 --phi 0", "--alpha: give one value"},
      {"directional --material glass --alpha 45 --theta 10 --phi 0 --model sp,rigorous",
       "--model: give one model"},
      {"directional --material glass --alpha 45 --phi 0", "--theta"},
  });
}

// Figure sizes, steps, unwritable outputs (nothing is written), unknown subcommands.
TEST(OchreVGroove, BadFigureOptionsExitWithTwoAndLeaveNoFile) {
  expect_bad_input({
      {"maps --material glass --alpha 45 --size 2 -o m.png", "--size: 2 pixels is outside"},
      {"maps --material glass,Xx --alpha 45 -o m.png", "--material: unknown material 'Xx'"},
      {"maps --material glass --alpha 200 -o m.png", "--alpha: dihedral angle 200"},
      {"maps --material glass --alpha 45 -o missing_dir/m.png", "missing_dir"},
      {"maps --material glass --alpha 45 -o m.png --counts missing_dir/c.png", "missing_dir"},
      {"profile --material Si --alpha 45 --step 0 -o p.csv", "--step: 0 degrees is outside"},
      {"profile --material Si --alpha 45,60 -o p.csv", "--alpha: give one dihedral angle"},
      {"profile --material Si --alpha 45 -o missing_dir/p.csv", "missing_dir"},
      {"tables --quadrature 0", "--quadrature: 0 points"},
      {"frobnicate", "A subcommand is required"},
  });
}

// Compare: angles the explicit plate cannot take, sample counts, sizes, threads, the scene directory.
TEST(OchreVGroove, BadCompareOptionsExitWithTwoAndLeaveNoFile) {
  expect_bad_input({
      {"compare --material Si --alpha 0.5", "--alpha: dihedral angle 0.5 is outside [1, 179.9]"},
      {"compare --material Si --alpha 180", "--alpha: dihedral angle 180 is outside [1, 179.9]"},
      {"compare --material Si --alpha 45,x", "--alpha: 'x' is not a finite number"},
      {"compare --material Si --theta 86", "--theta: polar angle 86 is outside [0, 85]"},
      {"compare --material Si --theta -1", "--theta: polar angle -1 is outside [0, 85]"},
      {"compare --material Si --phi 0,,90", "--phi: empty item in '0,,90'"},
      {"compare --material Si --phi inf", "--phi: 'inf' is not a finite number"},
      {"compare --material Si,Pt", "--material: unknown material 'Pt'"},
      {"compare --alpha 45", "give the facet material"},
      {"compare --material Si --spp 0", "--spp: 0 is outside [1, 16777216]"},
      {"compare --material Si --resolution 1", "--resolution: 1 pixels is outside [2, 4096]"},
      {"compare --material Si --threads -2", "--threads: -2 is negative"},
      {"compare --material Si --scene-dir missing_dir", "--scene-dir: missing_dir is not a directory"},
  });
}

}  // namespace
}  // namespace ochre::test::ochre_vgroove_test
