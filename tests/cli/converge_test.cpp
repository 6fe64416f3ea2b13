// ochre-converge end to end on a tiny Cornell box: the CSV it writes (rows, columns, error falling with
// the sample count), two sampler variants, and a bad reference path.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace ochre::test::converge_test {
namespace {

struct ConvergeResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

ConvergeResult run_converge(const std::string& args, const std::filesystem::path& dir) {
  const CommandResult r = run_tool("ochre-converge", args, dir);
  return {r.exit_code, r.output};
}

struct CsvRow {
  std::string variant;
  int spp = 0;
  double seconds = 0, relmse = 0, rmse = 0, relmse_x_seconds = 0;
};

// Reads the CSV; the header must be exactly the documented one.
std::vector<CsvRow> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "variant,spp,seconds,relmse,rmse,relmse_x_seconds");
  std::vector<CsvRow> rows;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    CsvRow row;
    fields >> row.variant >> row.spp >> row.seconds >> row.relmse >> row.rmse >> row.relmse_x_seconds;
    EXPECT_FALSE(fields.fail()) << line;
    rows.push_back(row);
  }
  return rows;
}

// The quoted path of the Cornell box scene (built with append: GCC 12 warns falsely on "'" + string).
std::string cornell_scene() {
  std::string quoted = "'";
  quoted.append((source_dir() / "scenes" / "cornell-box" / "cornell-box.json").string()).append("'");
  return quoted;
}

std::string cornell_args() {
  return cornell_scene() + " --width 32 --height 32 --spp 1,4,16 --threads 2 --reference auto";
}

TEST(Converge, AutoReferenceCsvErrorFallsWithSampleCount) {
  const auto dir = scratch_dir();
  const ConvergeResult r = run_converge(cornell_args() + " --csv out.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("reference: auto, rendered here at 256 spp"), std::string::npos) << r.output;

  const std::vector<CsvRow> rows = read_csv(dir / "out.csv");
  ASSERT_EQ(rows.size(), 3u);
  const int expected_spp[3] = {1, 4, 16};
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].variant, "base");
    EXPECT_EQ(rows[i].spp, expected_spp[i]);
    EXPECT_GT(rows[i].seconds, 0.0);
    EXPECT_GT(rows[i].relmse, 0.0);
    EXPECT_NEAR(rows[i].relmse_x_seconds, rows[i].relmse * rows[i].seconds, 1e-6 * rows[i].relmse_x_seconds);
  }
  // 4x the samples: the variance part of the error falls about 4x; ask for at least 2x.
  EXPECT_LT(rows[1].relmse, 0.5 * rows[0].relmse);
  EXPECT_LT(rows[2].relmse, 0.5 * rows[1].relmse);
  EXPECT_LT(rows[1].rmse, rows[0].rmse);
  EXPECT_LT(rows[2].rmse, rows[1].rmse);
}

TEST(Converge, TwoSamplerVariantsBothAppearWithEqualTimeRatio) {
  const auto dir = scratch_dir();
  const ConvergeResult r = run_converge(
      cornell_args() +
          " --variant independent:sampler=independent --variant sobol:sampler=sobol --csv out.csv",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<CsvRow> rows = read_csv(dir / "out.csv");
  ASSERT_EQ(rows.size(), 6u);
  std::map<std::string, std::vector<double>> relmse;
  for (const CsvRow& row : rows) relmse[row.variant].push_back(row.relmse);
  ASSERT_EQ(relmse.size(), 2u);
  ASSERT_EQ(relmse["independent"].size(), 3u);
  ASSERT_EQ(relmse["sobol"].size(), 3u);
  // The two samplers draw different sample values: their errors differ.
  EXPECT_NE(relmse["independent"][2], relmse["sobol"][2]);
  EXPECT_NE(r.output.find("relMSE(sobol) / relMSE(independent)"), std::string::npos) << r.output;
}

// integrator.branches as a variant: four paths per camera sample, less error at the largest count than one.
TEST(Converge, BranchesVariantLowersTheErrorPerSample) {
  const auto dir = scratch_dir();
  const ConvergeResult r =
      run_converge(cornell_args() + " --variant one:branches=1 --variant four:branches=4 --csv out.csv", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::map<std::string, std::vector<double>> relmse;
  for (const CsvRow& row : read_csv(dir / "out.csv")) relmse[row.variant].push_back(row.relmse);
  ASSERT_EQ(relmse["one"].size(), 3u);
  ASSERT_EQ(relmse["four"].size(), 3u);
  EXPECT_LT(relmse["four"][2], relmse["one"][2]);
  EXPECT_NE(r.output.find("relMSE(four) / relMSE(one)"), std::string::npos) << r.output;

  const ConvergeResult bad = run_converge(cornell_args() + " --variant many:branches=65", dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("branches must be in [1, 64]"), std::string::npos) << bad.output;
}

TEST(Converge, MissingReferenceExitsTwoNamingIt) {
  const auto dir = scratch_dir();
  const ConvergeResult r = run_converge(
      cornell_scene() + " --spp 1 --width 8 --height 8 --reference no_such_reference.exr --csv out.csv", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no_such_reference.exr"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
}

TEST(Converge, UnknownVariantSettingExitsTwoNamingIt) {
  const auto dir = scratch_dir();
  const ConvergeResult r = run_converge(cornell_args() + " --variant fast:samplr=sobol", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("samplr"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ochre::test::converge_test
