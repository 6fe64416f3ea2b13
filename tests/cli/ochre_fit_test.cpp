// ochre-fit end to end (docs/tools.md, docs/materials/powder.md "Fitting measurements"): the powder
// parameters recovered from synthetic goniophotometer data (1 % noise: within tolerance and within 3.5
// reported standard errors; no noise, from a start away from the truth: to 1e-6), the written material
// rendering with `ochre render` and holding the fitted values (ochre-brdf evaluates it to the fit), progress
// lines and -q, deterministic synthetic data, and every bad-input path (exit code 2, a message naming the
// file, line and column or the option, no output file created, an existing one untouched).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "cli/file_test_support.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::ochre_fit_test {
namespace {

namespace fs = std::filesystem;

const char* kTool = "ochre-fit";
const std::array<const char*, 6> kParams = {"volume_amplitude",  "g", "kappa", "radius", "surface_amplitude",
                                            "correlation_length"};
// The truth of the synthetic data: a hematite powder of 0.12 um grains with a modest specular peak.
const std::array<double, 6> kTruth = {0.8, 0.3, 1.5, 0.12, 5e-6, 3.0};

std::string truth_params() {
  std::string items;
  for (size_t p = 0; p < kParams.size(); ++p)
    items += fmt::format("{}{}={}", p ? "," : "", kParams[p], kTruth[p]);
  return items;
}

// Runs ochre-fit with progress lines on (OCHRE_PROGRESS=plain; run_tool turns them off): stdout and stderr
// apart.
struct SplitResult {
  int exit_code = -1;
  std::string out, err;
};
SplitResult run_fit_with_progress(const std::string& args, const fs::path& dir) {
  const std::string command = fmt::format("cd '{}' && OCHRE_PROGRESS=plain '{}' {} 2> stderr.txt",
                                          dir.string(), (bin_dir() / kTool).string(), args);
  const CommandResult r = run_shell(command);
  return {r.exit_code, r.output, read_file_contents(dir / "stderr.txt")};
}

struct Estimate {
  double value = NAN, standard_error = NAN;
};

// The parameter table of the summary: "  kappa      1.50116  +- 0.00959    (0.64 %)  1/um".
std::map<std::string, Estimate> parse_summary(const std::string& out) {
  std::map<std::string, Estimate> table;
  const std::regex row(R"(^  ([a-z_]+) +(\S+)  (?:\+- (\S+))?)");
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row) ||
        std::find(kParams.begin(), kParams.end(), m[1].str()) == kParams.end())
      continue;
    Estimate e;
    e.value = std::stod(m[2].str());
    if (m[3].matched) e.standard_error = std::stod(m[3].str());
    table[m[1].str()] = e;
  }
  return table;
}

void synthesize(const fs::path& dir, const std::string& args) {
  const CommandResult r = run_tool(kTool, "powder --synthesize data.csv " + args, dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

TEST(OchreFit, RecoversKnownParametersFromOnePercentNoiseWithinTheirReportedUncertainty) {
  const fs::path dir = scratch_dir();
  // 948 measurements: incidences 0, 20, 40, 60 deg; planes at azimuths 0, 30, 60, 90, 135 deg (in and
  // out of the plane of incidence); the backscattering peak every 2 deg; 450, 550 and 650 nm.
  synthesize(dir, "--params " + truth_params() + " --noise 0.01 --seed 1");
  const SplitResult r =
      run_fit_with_progress("powder --data data.csv -o fit.json --plot fit.png --csv fit.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::map<std::string, Estimate> fit = parse_summary(r.out);
  // Tolerances: about 5 standard errors of this sampling and noise (kappa, set by the width of the
  // backscattering peak alone, is the least precise).
  const std::array<double, 6> relative_tolerance = {0.01, 0.01, 0.05, 0.002, 0.01, 0.01};
  for (size_t p = 0; p < kParams.size(); ++p) {
    SCOPED_TRACE(kParams[p]);
    ASSERT_TRUE(fit.count(kParams[p])) << r.out;
    const Estimate& e = fit.at(kParams[p]);
    EXPECT_NEAR(e.value, kTruth[p], relative_tolerance[p] * kTruth[p]) << r.out;
    ASSERT_TRUE(e.standard_error > 0.0) << r.out;
    EXPECT_LE(std::abs(e.value - kTruth[p]), 3.5 * e.standard_error) << r.out;
  }
  // The fit's residuals are the noise: relative RMSE about 1 %.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(relative RMSE (\S+) %)"))) << r.out;
  EXPECT_NEAR(std::stod(m[1].str()), 1.0, 0.1);
  EXPECT_TRUE(contains(r.out, "MSE ")) << r.out;
  // Progress: the grid, a line every 10 evaluations of each local run with the current MSE, each run's end.
  EXPECT_TRUE(contains(r.err, "ochre-fit: coarse grid: 20160 points")) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(ochre-fit: run 1, evaluation 10: relative MSE \S+\n)")))
      << r.err;
  EXPECT_TRUE(
      std::regex_search(r.err, std::regex(R"(ochre-fit: run 1 \(from grid start 1 .*after \d+ evaluations)")))
      << r.err;
  // The outputs: the material, a PNG, a row per measurement.
  EXPECT_TRUE(fs::exists(dir / "fit.json"));
  EXPECT_EQ(read_file_contents(dir / "fit.png").substr(1, 3), "PNG");
  std::istringstream table(read_file_contents(dir / "fit.csv"));
  std::string header;
  std::getline(table, header);
  EXPECT_EQ(header, "theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf,fit,residual,used");
  int rows = 0;
  for (std::string line; std::getline(table, line);) ++rows;
  EXPECT_EQ(rows, 948);
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(OchreFit, RecoversNoiseFreeDataFromAStartAwayFromTheTruthTightly) {
  const fs::path dir = scratch_dir();
  synthesize(dir, "--params " + truth_params() + " --noise 0");
  const CommandResult r =
      run_tool(kTool,
               "powder --data data.csv -o fit.json --start volume_amplitude=1,g=0.1,kappa=0.8,"
               "radius=0.1,surface_amplitude=1e-5,correlation_length=2",
               dir, /*stdout_only=*/true);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "local runs (from --start")) << r.output;
  const nlohmann::json material =
      nlohmann::json::parse(read_file_contents(dir / "fit.json"))["materials"]["powder_fit"];
  for (size_t p = 0; p < kParams.size(); ++p)
    EXPECT_NEAR(material[kParams[p]].get<double>(), kTruth[p], 1e-6 * kTruth[p]) << kParams[p] << "\n"
                                                                                 << r.output;
}

// A quick fit (the nonlinear parameters held at the truth, the amplitudes fitted) for the tests of the
// outputs.
const char* kFixNonlinear = "--fix g=0.3,kappa=1.5,radius=0.12,correlation_length=3";

TEST(OchreFit, WrittenMaterialRendersAndHoldsTheFittedParameters) {
  const fs::path dir = scratch_dir();
  synthesize(dir, "--params " + truth_params() + " --noise 0.01 --lambda 450,650");
  const CommandResult r = run_tool(
      kTool, fmt::format("powder --data data.csv {} -o fit.json --csv fit.csv", kFixNonlinear), dir, true);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::map<std::string, Estimate> printed = parse_summary(r.output);
  const nlohmann::json scene = nlohmann::json::parse(read_file_contents(dir / "fit.json"));
  const nlohmann::json& material = scene["materials"]["powder_fit"];
  EXPECT_EQ(material["type"], "powder");
  EXPECT_EQ(material["pigment"], "hematite");
  for (const char* name : kParams)
    EXPECT_NEAR(material[name].get<double>(), printed.at(name).value, 5e-6 * std::abs(printed.at(name).value))
        << name;
  EXPECT_EQ(material["g"].get<double>(), 0.3);  // held values are written as given

  // `ochre render` renders the file as it is.
  const CommandResult render =
      run_ochre("render fit.json -o preview.exr --resolution 16x16 --spp 4 --threads 1 -q", dir);
  ASSERT_EQ(render.exit_code, 0) << render.output;
  EXPECT_TRUE(fs::exists(dir / "preview.exr"));

  // The renderer's closure is the fitted BRDF: ochre-brdf evaluates the file at the measurements' geometry
  // to the fit (the renderer interpolates the grains' albedo from a table, within 2e-4).
  std::istringstream fitted(read_file_contents(dir / "fit.csv"));
  std::string line;
  std::getline(fitted, line);
  std::string pairs = "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm\n";
  std::vector<double> expected;
  for (int row = 0; std::getline(fitted, line) && row < 400; ++row) {
    if (row % 20) continue;
    double f[9];
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &f[0], &f[1], &f[2], &f[3],
                          &f[4], &f[5], &f[6], &f[7], &f[8]),
              9);
    const double d = std::numbers::pi / 180.0;
    pairs += fmt::format("{},{},{},{},{},{},{}\n", std::sin(f[0] * d) * std::cos(f[1] * d),
                         std::sin(f[0] * d) * std::sin(f[1] * d), std::cos(f[0] * d),
                         std::sin(f[2] * d) * std::cos(f[3] * d), std::sin(f[2] * d) * std::sin(f[3] * d),
                         std::cos(f[2] * d), f[4]);
    expected.push_back(f[6]);
  }
  write_text(dir / "pairs.csv", pairs);
  const CommandResult eval =
      run_tool("ochre-brdf", "eval --material fit.json --input pairs.csv --output values.csv", dir);
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  std::istringstream values(read_file_contents(dir / "values.csv"));
  std::getline(values, line);
  for (double want : expected) {
    ASSERT_TRUE(std::getline(values, line));
    const double got = std::stod(line.substr(line.rfind(',') + 1));
    EXPECT_NEAR(got, want, 1e-3 * want) << line;
  }
}

TEST(OchreFit, PigmentFileIsWrittenRelativeToTheMaterial) {
  const fs::path dir = scratch_dir();
  // Hematite's ordinary ray as a table, the grains' index at 450 and 650 nm.
  write_text(dir / "nk.csv", "lambda_nm,n,k\n400,3.0,1.2\n700,2.9,0.05\n");
  fs::create_directories(dir / "out");
  synthesize(dir, "--params " + truth_params() + " --pigment-file nk.csv --noise 0.01 --lambda 450,650");
  const CommandResult r = run_tool(
      kTool, fmt::format("powder --data data.csv --pigment-file nk.csv {} -o out/fit.json -q", kFixNonlinear),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json scene = nlohmann::json::parse(read_file_contents(dir / "out/fit.json"));
  EXPECT_EQ(scene["materials"]["powder_fit"]["pigment_file"], "../nk.csv");
  EXPECT_FALSE(scene["materials"]["powder_fit"].contains("pigment"));
  const CommandResult render =
      run_ochre("render out/fit.json -o preview.exr --resolution 8x8 --spp 1 --threads 1 -q", dir);
  EXPECT_EQ(render.exit_code, 0) << render.output;
}

TEST(OchreFit, QuietFlagSilencesTheProgressLines) {
  const fs::path dir = scratch_dir();
  synthesize(dir, "--params " + truth_params() + " --lambda 550");
  const SplitResult loud =
      run_fit_with_progress(fmt::format("powder --data data.csv {}", kFixNonlinear), dir);
  ASSERT_EQ(loud.exit_code, 0) << loud.out << loud.err;
  EXPECT_TRUE(contains(loud.err, "ochre-fit: run 1 (from grid start 1")) << loud.err;
  const SplitResult quiet =
      run_fit_with_progress(fmt::format("powder --data data.csv {} -q", kFixNonlinear), dir);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.out << quiet.err;
  EXPECT_EQ(quiet.err, "");
  // The same summary but for the time it took.
  const std::regex seconds(R"([0-9.]+ s\n)");
  EXPECT_EQ(std::regex_replace(quiet.out, seconds, "T s\n"), std::regex_replace(loud.out, seconds, "T s\n"));
}

TEST(OchreFit, SynthesizeIsDeterministicPerSeed) {
  const fs::path dir = scratch_dir();
  const auto make = [&](const std::string& out, const std::string& args) {
    const CommandResult r = run_tool(kTool, "powder --synthesize " + out + " " + args, dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output, "wrote 948 measurements to " + out + "\n");
    return read_file_contents(dir / out);
  };
  const std::string a = make("a.csv", "--seed 7"), b = make("b.csv", "--seed 7"),
                    c = make("c.csv", "--seed 8");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_TRUE(contains(a, "\ntheta_i,phi_i,theta_o,phi_o,lambda_nm,brdf\n")) << a.substr(0, 400);
  // --geometry: the geometries and wavelengths of a measurements file, in its order.
  write_text(dir / "mine.csv",
             "brdf,lambda_nm,theta_i,phi_i,theta_o,phi_o\n1,500,10,0,30,180\n1,600,45,90,5,0\n");
  const CommandResult r = run_tool(kTool, "powder --synthesize d.csv --geometry mine.csv --noise 0", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string d = read_file_contents(dir / "d.csv");
  EXPECT_TRUE(contains(d, "\n10,0,30,180,500,")) << d;
  EXPECT_TRUE(contains(d, "\n45,90,5,0,600,")) << d;
}

// ---------------------------------------------------------------------------------------------------
// Bad input: exit 2, a message naming the file and line and column, or the option; no output file created
// and an existing one untouched.

struct BadCase {
  const char* name;
  const char* data;  // data.csv ("" for none)
  const char* args;  // after "powder"
  std::vector<std::string> message;
};

const char* kHeader = "theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf\n";
std::string rows_of(int count) {
  std::string rows = kHeader;
  for (int i = 0; i < count; ++i) rows += fmt::format("{},0,{},180,550,0.05\n", i % 60, (i * 7) % 80);
  return rows;
}
const std::string kGood = rows_of(12);

// The case's name for gtest's messages and ctest's test names (not its bytes).
void PrintTo(const BadCase& c, std::ostream* out) {
  *out << c.name;
}

class OchreFitBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(OchreFitBadInput, ExitsTwoNamingTheCauseAndWritesNothing) {
  const BadCase& c = GetParam();
  const fs::path dir = scratch_dir();
  if (*c.data) write_text(dir / "data.csv", c.data);
  write_old_file(dir / "old.json", "{\"an\": \"existing output\"}\n");
  const FileSnapshot before = snapshot(dir / "old.json");
  const FileSnapshot data_before = *c.data ? snapshot(dir / "data.csv") : FileSnapshot{};
  const std::string args = fmt::format("powder {} -o old.json --plot new.png --csv new.csv", c.args);
  const CommandResult r = run_tool(kTool, args, dir);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  for (const std::string& part : c.message) EXPECT_TRUE(contains(r.output, part)) << part << "\n" << r.output;
  EXPECT_TRUE(snapshot(dir / "old.json") == before);
  if (*c.data) {
    EXPECT_TRUE(snapshot(dir / "data.csv") == data_before);
  }
  EXPECT_FALSE(fs::exists(dir / "new.png"));
  EXPECT_FALSE(fs::exists(dir / "new.csv"));
  EXPECT_TRUE(temporaries_in(dir).empty());
}

const std::string kMissingColumn = "theta_i,phi_i,theta_o,lambda_nm,brdf\n0,0,10,550,0.05\n";
const std::string kDuplicateColumn =
    "theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf,brdf\n0,0,10,0,550,0.05,0.05\n";
const std::string kUnknownColumn = "theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf,sigma\n0,0,10,0,550,0.05,1\n";
const std::string kNotANumber = kGood + "10,0,abc,180,550,0.05\n";
const std::string kNaN = kGood + "10,0,20,180,550,nan\n";
const std::string kInfinity = kGood + "10,0,20,180,inf,0.05\n";
const std::string kThetaI = kGood + "95,0,20,180,550,0.05\n";
const std::string kThetaO = kGood + "10,0,-5,180,550,0.05\n";
const std::string kPhi = kGood + "10,0,20,400,550,0.05\n";
const std::string kLambda = kGood + "10,0,20,180,300,0.05\n";
const std::string kNegative = kGood + "10,0,20,180,550,-0.01\n";
const std::string kZero = kGood + "10,0,20,180,550,0\n";
const std::string kFields = kGood + "10,0,20,180,550\n";
const std::string kFiveRows = rows_of(5);

const BadCase kBadCases[] = {
    {"MissingFile", "", "--data nope.csv", {"nope.csv", "cannot open"}},
    {"MissingColumn",
     kMissingColumn.c_str(),
     "--data data.csv",
     {"data.csv: line 1: header: missing column 'phi_o'"}},
    {"DuplicateColumn",
     kDuplicateColumn.c_str(),
     "--data data.csv",
     {"data.csv: line 1: header: column 'brdf' appears twice"}},
    {"UnknownColumn",
     kUnknownColumn.c_str(),
     "--data data.csv",
     {"data.csv: line 1: header: unknown column 'sigma'"}},
    {"NonNumeric",
     kNotANumber.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column theta_o: 'abc' is not a finite number"}},
    {"NaN",
     kNaN.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column brdf: 'nan' is not a finite number"}},
    {"Infinity",
     kInfinity.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column lambda_nm: 'inf' is not a finite number"}},
    {"ThetaIOutOfRange",
     kThetaI.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column theta_i: 95 is outside [0, 90) degrees"}},
    {"ThetaONegative",
     kThetaO.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column theta_o: -5 is outside [0, 90) degrees"}},
    {"PhiOutOfRange",
     kPhi.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column phi_o: 400 is outside [-360, 360] degrees"}},
    {"WavelengthOutOfRange",
     kLambda.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column lambda_nm: 300 nm is outside"}},
    {"NegativeBrdf",
     kNegative.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column brdf: -0.01 is negative"}},
    {"ZeroBrdfWithRelativeResiduals",
     kZero.c_str(),
     "--data data.csv",
     {"data.csv: line 14: column brdf: 0 is not > 0", "--residuals"}},
    {"WrongFieldCount", kFields.c_str(), "--data data.csv", {"data.csv: line 14: 5 fields, expected 6"}},
    {"HeaderOnly", kHeader, "--data data.csv", {"data.csv: no measurements"}},
    {"TooFewRows",
     kFiveRows.c_str(),
     "--data data.csv",
     {"data.csv: 5 measurement(s) for 6 free parameter(s)"}},
    {"TooFewRowsAfterMaxThetaI",
     kGood.c_str(),
     "--data data.csv --max-theta-i 2",
     {"data.csv: 3 measurement(s) with theta_i <= 2 for 6 free"}},
    {"BoundsReversed",
     kGood.c_str(),
     "--data data.csv --bounds kappa=5:1",
     {"--bounds 'kappa=5:1': the lower bound 5 is not below the upper bound 1"}},
    {"BoundsMalformed",
     kGood.c_str(),
     "--data data.csv --bounds kappa=5",
     {"--bounds 'kappa=5': expected NAME=LOWER:UPPER"}},
    {"BoundsOutsideTheModel",
     kGood.c_str(),
     "--data data.csv --bounds g=-2:0.5",
     {"--bounds 'g=-2:0.5': g must be in [-0.99, 0.99]"}},
    {"StartOutsideDefaultBounds",
     kGood.c_str(),
     "--data data.csv --start kappa=100",
     {"--start kappa=100: outside the bounds [0.01, 50] of kappa"}},
    {"StartOutsideGivenBounds",
     kGood.c_str(),
     "--data data.csv --bounds radius=0.01:0.1 --start radius=0.2",
     {"--start radius=0.2: outside the bounds [0.01, 0.1] of radius"}},
    {"StartOfAFixedParameter",
     kGood.c_str(),
     "--data data.csv --fix g=0 --start g=0.1",
     {"--start: g is held by --fix g=0"}},
    {"BoundsOfAFixedParameter",
     kGood.c_str(),
     "--data data.csv --fix g=0 --bounds g=0:0.5",
     {"--bounds: g is held by --fix g=0"}},
    {"FixUnknownParameter",
     kGood.c_str(),
     "--data data.csv --fix sigma=1",
     {"--fix 'sigma=1': unknown parameter 'sigma'", "correlation_length"}},
    {"FixOutsideTheModel",
     kGood.c_str(),
     "--data data.csv --fix radius=50",
     {"--fix 'radius=50': radius must be in [0.002, 20]"}},
    {"FixNotANumber",
     kGood.c_str(),
     "--data data.csv --fix kappa=nan",
     {"--fix 'kappa=nan': 'nan' is not a finite number"}},
    {"FixTwice",
     kGood.c_str(),
     "--data data.csv --fix g=0,g=0.1",
     {"--fix 'g=0.1': parameter 'g' is given twice"}},
    {"UnknownResiduals",
     kGood.c_str(),
     "--data data.csv --residuals log",
     {"--residuals: 'log' is not absolute or relative"}},
    {"MaxThetaIOutOfRange",
     kGood.c_str(),
     "--data data.csv --max-theta-i 95",
     {"--max-theta-i: 95 is outside [0, 90] degrees"}},
    {"UnknownPigment",
     kGood.c_str(),
     "--data data.csv --pigment gold",
     {"--pigment: unknown pigment 'gold'", "hematite"}},
    {"MissingPigmentFile",
     kGood.c_str(),
     "--data data.csv --pigment-file nk.csv",
     {"--pigment-file", "nk.csv"}},
    {"UnknownOption", kGood.c_str(), "--data data.csv --csv2 x", {"--csv2"}},
    {"DataAndSynthesize", kGood.c_str(), "--data data.csv --synthesize x.csv", {"--synthesize"}},
};

std::string case_name(const ::testing::TestParamInfo<BadCase>& info) {
  return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(Cases, OchreFitBadInput, ::testing::ValuesIn(kBadCases), case_name);

TEST(OchreFit, MeasurementsOrPigmentThatAreNotRegularFilesAreRefused) {
  const fs::path dir = scratch_dir();
  make_fifo(dir / "fifo.csv");
  write_text(dir / "data.csv", kGood);
  for (const std::string& args : {std::string("--data fifo.csv"), std::string("--data /dev/zero"),
                                  std::string("--data data.csv --pigment-file fifo.csv")}) {
    const CommandResult r = run_tool(kTool, "powder " + args + " --csv fit.csv", dir, false, 20);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "not a regular file")) << args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "fit.csv")) << args;
  }
}

TEST(OchreFit, AnOutputThatIsAnInputIsRefused) {
  const fs::path dir = scratch_dir();
  write_text(dir / "data.csv", kGood);
  const FileSnapshot before = snapshot(dir / "data.csv");
  const CommandResult r = run_tool(kTool, "powder --data data.csv --csv data.csv", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "data.csv")) << r.output;
  EXPECT_TRUE(snapshot(dir / "data.csv") == before);
}

TEST(OchreFit, AnOutputInAMissingDirectoryIsRefusedBeforeFitting) {
  const fs::path dir = scratch_dir();
  write_text(dir / "data.csv", kGood);
  const CommandResult r = run_tool(kTool, "powder --data data.csv --csv fit.csv -o nowhere/fit.json", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "nowhere/fit.json")) << r.output;
  EXPECT_FALSE(contains(r.output, "parameter ")) << r.output;  // no fit was run
  EXPECT_FALSE(fs::exists(dir / "fit.csv"));
}

TEST(OchreFit, BadSynthesizeOptionsNameTheOption) {
  const fs::path dir = scratch_dir();
  write_old_file(dir / "out.csv", "old\n");
  const FileSnapshot before = snapshot(dir / "out.csv");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--params kappa=-1", "--params 'kappa=-1': kappa must be in [1e-06, 1000000]"},
      {"--params thickness=3", "--params 'thickness=3': unknown parameter 'thickness'"},
      {"--noise 1.5", "--noise: 1.5 is outside [0, 1)"},
      {"--noise -0.1", "--noise: -0.1 is outside [0, 1)"},
      {"--lambda 900", "--lambda: 900 nm is outside ochre's spectral range [360, 830] nm"},
      {"--geometry nope.csv", "nope.csv"},
      {"--seed -1", "--seed"},
  };
  for (const auto& [args, message] : cases) {
    const CommandResult r = run_tool(kTool, "powder --synthesize out.csv " + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, message)) << args << "\n" << r.output;
    EXPECT_TRUE(snapshot(dir / "out.csv") == before) << args;
  }
  EXPECT_TRUE(temporaries_in(dir).empty());
}

}  // namespace
}  // namespace ochre::test::ochre_fit_test
