// ochre-brdf end to end (docs/tools.md): eval, albedo and chi2 on the Lambert material, whose BRDF is
// known exactly (color / pi above the surface, 0 below), and every bad-input path (exit code 2, a
// message naming the file, line, column or parameter, no output file left behind).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_runner.h"
#include "materials/core/pi.h"
#include "support/test_paths.h"

namespace ochre::test::ochre_brdf_test {
namespace {

const char* kLambert = R"({"type": "lambert", "color": 0.8})";
const char* kPairsHeader = "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm\n";

std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    std::string field;
    while (std::getline(s, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

void expect_no_leftovers(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
        << "temporary file left behind: " << entry.path();
}

TEST(OchreBrdf, EvalOfLambertIsColorOverPiAboveTheSurfaceAndZeroBelow) {
  const auto dir = scratch_dir();
  write_text(dir / "lambert.json", kLambert);
  // Unnormalised directions on purpose; the last three pairs have wi or wo below the surface.
  write_text(dir / "pairs.csv", std::string(kPairsHeader) +
                                    "0,0,1,0,0,1,550\n"
                                    "1,2,3,0.2,-0.1,5,400\n"
                                    "0.9,0,0.05,-3,1,0.2,700\n"
                                    "0.3,0.3,0.9,0.5,0,0.5,360\n"
                                    "0,0,-1,0,0,1,550\n"
                                    "0,1,1,0.2,0,-0.3,550\n"
                                    "0.5,0,-0.1,0.1,0.1,-2,830\n");
  const CommandResult r =
      run_tool("ochre-brdf", "eval --material lambert.json --input pairs.csv --output values.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string header;
  const auto rows = read_csv(dir / "values.csv", header);
  EXPECT_EQ(header, "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm,f");
  ASSERT_EQ(rows.size(), 7u);
  EXPECT_EQ(rows[1][0] + "," + rows[1][5] + "," + rows[1][6], "1,5,400")
      << "input fields repeated as written";
  for (size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 8u);
    const double f = std::stod(rows[i][7]);
    if (i < 4)
      EXPECT_NEAR(f, 0.8 / kPiD, 1e-6) << "pair " << i;
    else
      EXPECT_EQ(f, 0.0) << "pair " << i << " has a direction below the surface";
  }
  expect_no_leftovers(dir);
}

TEST(OchreBrdf, AlbedoOfLambertIsItsColorAtEveryAngle) {
  const auto dir = scratch_dir();
  write_text(dir / "lambert.json", kLambert);
  const CommandResult r =
      run_tool("ochre-brdf",
               "albedo --material lambert.json --angles 0,30,60,89 --samples 20000 --output albedo.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string header;
  const auto rows = read_csv(dir / "albedo.csv", header);
  EXPECT_EQ(header, "theta_deg,lambda_nm,mc_albedo,mc_se,quadrature_albedo,quadrature_error");
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 6u);
    const double mc = std::stod(row[2]), se = std::stod(row[3]), quad = std::stod(row[4]),
                 err = std::stod(row[5]);
    // Cosine sampling makes every Monte-Carlo weight exactly the colour; the quadrature of a constant
    // times cos theta is exact up to rounding.
    EXPECT_NEAR(mc, 0.8, 1e-5) << "theta " << row[0];
    EXPECT_LT(se, 1e-5);
    EXPECT_NEAR(quad, 0.8, 1e-5) << "theta " << row[0];
    EXPECT_LT(err, 1e-5);
  }
}

TEST(OchreBrdf, Chi2PassesForLambert) {
  const auto dir = scratch_dir();
  write_text(dir / "lambert.json", kLambert);
  const CommandResult r =
      run_tool("ochre-brdf",
               "chi2 --material lambert.json --incidence 0,45,85 --samples 200000 --output chi2.csv", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("PASS"), std::string::npos) << r.output;
  std::string header;
  const auto rows = read_csv(dir / "chi2.csv", header);
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) {
    EXPECT_EQ(row.back(), "yes");
    EXPECT_GT(std::stod(row[3]), std::stod(row[4])) << "p-value above the significance";
    EXPECT_EQ(row[5], "200000") << "every sample histogrammed";
  }
}

TEST(OchreBrdf, PicksANamedMaterialFromAMaterialsObject) {
  const auto dir = scratch_dir();
  write_text(
      dir / "two.json",
      R"({"materials": {"dark": {"type": "lambert", "color": 0.2}, "light": {"type": "lambert", "color": 0.9}}})");
  write_text(dir / "pairs.csv", std::string(kPairsHeader) + "0,0,1,0,0,1,550\n");
  CommandResult r = run_tool("ochre-brdf", "eval --material two.json --input pairs.csv --output v.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("choose one with --name"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("dark, light"), std::string::npos) << r.output;
  r = run_tool("ochre-brdf", "eval --material two.json --name light --input pairs.csv --output v.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string header;
  EXPECT_NEAR(std::stod(read_csv(dir / "v.csv", header).at(0).at(7)), 0.9 / kPiD, 1e-6);
}

struct BadCase {
  std::string name, material, pairs;
  std::vector<std::string> expected;  // substrings of the message
};

void expect_rejected(const BadCase& c, const std::filesystem::path& dir) {
  write_text(dir / "mat.json", c.material);
  write_text(dir / "pairs.csv", c.pairs);
  const CommandResult r =
      run_tool("ochre-brdf", "eval --material mat.json --input pairs.csv --output out.csv", dir);
  EXPECT_EQ(r.exit_code, 2) << c.name << "\n" << r.output;
  for (const std::string& s : c.expected)
    EXPECT_NE(r.output.find(s), std::string::npos) << c.name << ": message must contain '" << s << "'\n"
                                                   << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv")) << c.name << ": no partial output";
  expect_no_leftovers(dir);
}

const std::string kGoodPairs = std::string(kPairsHeader) + "0,0,1,0,0,1,550\n";

TEST(OchreBrdf, BadMaterialExitsWithTwoAndNamesTheFault) {
  const std::vector<BadCase> cases = {
      {"malformed json",
       "{\"type\": \"lambert\",\n \"color\": }",
       kGoodPairs,
       {"mat.json", "line 2", "malformed JSON"}},
      {"unknown parameter", R"({"type": "lambert", "colour": 0.8})", kGoodPairs, {"mat.json", "colour"}},
      {"unknown material type", R"({"type": "velvet"})", kGoodPairs, {"mat.json", "velvet"}},
  };
  for (size_t i = 0; i < cases.size(); ++i) expect_rejected(cases[i], scratch_dir() / std::to_string(i));
  const auto dir = scratch_dir() / "missing";
  write_text(dir / "pairs.csv", kGoodPairs);
  const CommandResult r =
      run_tool("ochre-brdf", "eval --material nope.json --input pairs.csv --output out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nope.json"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

TEST(OchreBrdf, BadPairsExitWithTwoAndNameTheLine) {
  const std::vector<BadCase> cases = {
      {"zero direction",
       kLambert,
       std::string(kPairsHeader) + "0,0,1,0,0,1,550\n0,0,0,0,0,1,550\n",
       {"pairs.csv", "line 3", "wi is the zero vector"}},
      {"not a number",
       kLambert,
       std::string(kPairsHeader) + "0,0,1,0,zero,1,550\n",
       {"pairs.csv", "line 2", "wo_y", "'zero'"}},
      {"missing column",
       kLambert,
       "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z\n0,0,1,0,0,1\n",
       {"pairs.csv", "line 1", "missing column 'lambda_nm'"}},
      {"field count",
       kLambert,
       std::string(kPairsHeader) + "0,0,1,0,0,1\n",
       {"pairs.csv", "line 2", "6 fields"}},
      {"wavelength out of range",
       kLambert,
       std::string(kPairsHeader) + "0,0,1,0,0,1,550\n0,0,1,0,0,1,1200\n",
       {"pairs.csv", "line 3", "lambda_nm", "1200"}},
  };
  for (size_t i = 0; i < cases.size(); ++i) expect_rejected(cases[i], scratch_dir() / std::to_string(i));
  const auto dir = scratch_dir() / "missing";
  write_text(dir / "mat.json", kLambert);
  CommandResult r = run_tool("ochre-brdf", "eval --material mat.json --input none.csv --output out.csv", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("none.csv"), std::string::npos) << r.output;
  r = run_tool("ochre-brdf", "albedo --material mat.json --angles 0,95", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--angles"), std::string::npos) << r.output;
  r = run_tool("ochre-brdf", "albedo --material mat.json --lambda 200", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--lambda"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

TEST(OchreBrdf, PlotWritesAPng) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-matplotlib is not installed";
  const auto dir = scratch_dir();
  write_text(dir / "lambert.json", kLambert);
  const CommandResult r = run_tool(
      "ochre-brdf", "plot --material lambert.json --output plot.png --incidence 0,60 --csv plot.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream png(dir / "plot.png", std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  std::string header;
  const auto rows = read_csv(dir / "plot.csv", header);
  EXPECT_EQ(header, "incidence_deg,theta_o_deg,phi_o_deg,f");
  EXPECT_EQ(rows.size(), 2u * 90u * 73u);
  expect_no_leftovers(dir);
}

// The Lambertian-sphere material (docs/materials/lambert_sphere.md) through the explorer: its BRDF is
// reciprocal (swapping wi and wo gives the same f), positive above the surface and 0 below, and its kd
// is the bond albedo 2 int rho(mu) mu dmu (d'Eon's definition), here from `albedo` at the Gauss-Legendre
// nodes of mu.
std::vector<std::pair<double, double>> gauss_legendre_unit(int n) {  // nodes and weights on [0, 1]
  std::vector<std::pair<double, double>> rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPiD * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {  // Newton on P_n(x) by its recurrence
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    rule.push_back({0.5 * (x + 1.0), 1.0 / ((1.0 - x * x) * dp * dp)});  // weight 2/((1-x^2)P'^2), halved
  }
  return rule;
}

TEST(OchreBrdf, LambertSphereIsReciprocalAndItsKdIsTheBondAlbedo) {
  const auto dir = scratch_dir();
  write_text(dir / "ls.json", R"({"type": "lambert_sphere", "kd": 0.8})");
  // Pairs and their swaps (backscatter, forward, side, grazing), then two with a direction below.
  const std::vector<std::string> pairs = {"0.3,0.1,0.9,0.5,-0.2,0.6", "0.9,0,0.1,-0.7,0.1,0.4",
                                          "0.2,0.8,0.3,0.6,0,0.7", "0.99,0,0.05,0.98,0.1,0.1"};
  std::string text = kPairsHeader;
  for (const std::string& p : pairs) text += p + ",550\n";
  for (const std::string& p : pairs) {
    const size_t third_comma = p.find(',', p.find(',', p.find(',') + 1) + 1);
    text += p.substr(third_comma + 1) + "," + p.substr(0, third_comma) + ",550\n";
  }
  text += "0,0,-1,0,0,1,550\n0.3,0.1,0.9,0.5,0,-0.2,550\n";
  write_text(dir / "pairs.csv", text);
  CommandResult r = run_tool("ochre-brdf", "eval --material ls.json --input pairs.csv --output f.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string header;
  const auto rows = read_csv(dir / "f.csv", header);
  ASSERT_EQ(rows.size(), 2 * pairs.size() + 2);
  for (size_t i = 0; i < pairs.size(); ++i) {
    const double f = std::stod(rows[i][7]), swapped = std::stod(rows[i + pairs.size()][7]);
    std::printf("lambert_sphere kd 0.8: f(%s) = %.6f, swapped %.6f\n", pairs[i].c_str(), f, swapped);
    EXPECT_GT(f, 0.0) << "pair " << i;
    EXPECT_NEAR(swapped, f, 1e-5 * f) << "pair " << i << " is not reciprocal";
  }
  EXPECT_EQ(std::stod(rows[2 * pairs.size()][7]), 0.0) << "light below the surface";
  EXPECT_EQ(std::stod(rows[2 * pairs.size() + 1][7]), 0.0) << "viewer below the surface";

  const auto rule = gauss_legendre_unit(12);
  std::string angles;
  for (const auto& node : rule) {  // appended piecewise: GCC 12 warns falsely on "," + std::string
    if (!angles.empty()) angles += ',';
    angles += fmt::format("{:.10f}", std::acos(node.first) * 180.0 / kPiD);
  }
  r = run_tool("ochre-brdf",
               "albedo --material ls.json --angles " + angles + " --samples 2000 --output a.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto albedo_rows = read_csv(dir / "a.csv", header);
  ASSERT_EQ(albedo_rows.size(), rule.size());
  double bond = 0.0;
  for (size_t i = 0; i < rule.size(); ++i) {
    const double rho = std::stod(albedo_rows[i][4]);
    EXPECT_GT(rho, 0.0);
    EXPECT_LT(rho, 1.0) << "theta " << albedo_rows[i][0];
    bond += 2.0 * rule[i].second * rule[i].first * rho;
  }
  std::printf("lambert_sphere kd 0.8: bond albedo from 12 directional albedos = %.5f\n", bond);
  EXPECT_NEAR(bond, 0.8, 0.8 * 0.005);
}

}  // namespace
}  // namespace ochre::test::ochre_brdf_test
