// ochre-diff end to end: an image against itself, against perturbed copies (one pixel, +5 % exposure),
// the heat-map, thresholds and exit codes, bad input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"
#include "support/test_paths.h"

namespace ochre::test::ochre_diff_test {
namespace {

struct DiffResult {
  int exit_code = -1;
  std::string output;
};

// Runs `ochre-diff ARGS` in dir; stderr is merged into the output unless stdout_only.
DiffResult run_diff(const std::string& args, const std::filesystem::path& dir, bool stdout_only = false) {
  const CommandResult r = run_tool("ochre-diff", args, dir, stdout_only);
  return {r.exit_code, r.output};
}

constexpr int kWidth = 16, kHeight = 12;

// A smooth colour gradient in [0.05, 0.85], channels stored as separate EXR planes.
std::vector<float> gradient() {
  std::vector<float> rgb(3 * kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = 3 * static_cast<size_t>(y * kWidth + x);
      rgb[i] = 0.05f + 0.8f * x / (kWidth - 1);
      rgb[i + 1] = 0.05f + 0.8f * y / (kHeight - 1);
      rgb[i + 2] = 0.3f;
    }
  }
  return rgb;
}

void write_rgb_exr(const std::filesystem::path& path, const std::vector<float>& rgb, int width = kWidth,
                   int height = kHeight) {
  ExrImage image;
  image.width = width;
  image.height = height;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    std::vector<float> plane(static_cast<size_t>(width * height));
    for (size_t p = 0; p < plane.size(); ++p) plane[p] = rgb[3 * p + c];
    image.channels.emplace_back(names[c], std::move(plane));
  }
  image.chromaticities = rec709_chromaticities();
  write_exr(path, image);
}

nlohmann::json diff_json(const std::string& args, const std::filesystem::path& dir, int expected_exit) {
  const DiffResult r = run_diff(args + " --json", dir, true);
  EXPECT_EQ(r.exit_code, expected_exit) << r.output;
  return nlohmann::json::parse(r.output);
}

TEST(OchreDiff, ImageAgainstItselfIsAllZero) {
  const auto dir = scratch_dir();
  write_rgb_exr(dir / "a.exr", gradient());
  const auto j = diff_json("a.exr a.exr --max-rmse 0 --max-relmse 0 --max-error 0 --max-de 0", dir, 0);
  EXPECT_EQ(j["rmse"], 0.0);
  EXPECT_EQ(j["relmse"], 0.0);
  EXPECT_EQ(j["max_error"], 0.0);
  EXPECT_EQ(j["mean_de00"], 0.0);
  EXPECT_EQ(j["max_de00"], 0.0);
  EXPECT_EQ(j["pass"], true);
  const DiffResult table = run_diff("a.exr a.exr", dir);
  EXPECT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("mean-de00"), std::string::npos) << table.output;
}

TEST(OchreDiff, OnePixelChangedIsFoundAndShownRed) {
  const auto dir = scratch_dir();
  std::vector<float> rgb = gradient();
  write_rgb_exr(dir / "ref.exr", rgb);
  const size_t changed = 3 * static_cast<size_t>(7 * kWidth + 5);  // x = 5, y = 7
  const float old_green = rgb[changed + 1];
  rgb[changed + 1] = 0.95f;
  write_rgb_exr(dir / "test.exr", rgb);

  const auto j = diff_json("test.exr ref.exr --max-error 0.1 --heatmap heat.png", dir, 4);
  EXPECT_NEAR(j["max_error"].get<double>(), 0.95 - old_green, 1e-6);
  EXPECT_EQ(j["max_error_at"]["x"], 5);
  EXPECT_EQ(j["max_error_at"]["y"], 7);
  EXPECT_EQ(j["max_error_at"]["channel"], "G");
  const double d = 0.95 - old_green;
  EXPECT_NEAR(j["rmse"].get<double>(), std::sqrt(d * d / (3.0 * kWidth * kHeight)), 1e-6);
  EXPECT_GT(j["max_de00"].get<double>(), 3.0);
  ASSERT_EQ(j["exceeded"].size(), 1u);

  const DiffResult r = run_diff("test.exr ref.exr --max-error 0.1 --max-rmse 1", dir);
  EXPECT_EQ(r.exit_code, 4);  // a threshold exceeded (docs/cli.md, "Exit codes")
  EXPECT_NE(r.output.find("threshold exceeded: max-error"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("exceeded: rmse"), std::string::npos) << r.output;

  int w = 0, h = 0;
  const auto heat = read_png_rgb8(dir / "heat.png", w, h);
  ASSERT_EQ(w, kWidth);
  ASSERT_EQ(h, kHeight);
  for (int p = 0; p < kWidth * kHeight; ++p) {
    const uint8_t* c = &heat[3 * static_cast<size_t>(p)];
    if (3 * static_cast<size_t>(p) == changed) {
      EXPECT_GT(c[0], 150);  // red
      EXPECT_LT(c[1], 40);
      EXPECT_LT(c[2], 40);
    } else {
      EXPECT_EQ(c[0] + c[1] + c[2], 3 * 255) << p;  // white: no error
    }
  }
}

TEST(OchreDiff, FivePercentExposureChangeIsDetected) {
  const auto dir = scratch_dir();
  const std::vector<float> reference = gradient();
  std::vector<float> brighter = reference;
  double relmse = 0.0;
  for (size_t i = 0; i < brighter.size(); ++i) {
    brighter[i] *= 1.05f;
    const double d = static_cast<double>(brighter[i]) - reference[i];
    relmse += d * d / (static_cast<double>(reference[i]) * reference[i] + 1e-2);
  }
  relmse /= static_cast<double>(brighter.size());
  write_rgb_exr(dir / "ref.exr", reference);
  write_rgb_exr(dir / "bright.exr", brighter);

  const auto j = diff_json("bright.exr ref.exr --max-relmse 1e-4 --max-de 0.5", dir, 4);
  EXPECT_NEAR(j["relmse"].get<double>(), relmse, 1e-9);
  EXPECT_GT(j["mean_de00"].get<double>(), 0.5);  // +5 % is visible: about 1-2 dE00 on mid tones
  EXPECT_LT(j["mean_de00"].get<double>(), 5.0);
  EXPECT_EQ(j["exceeded"].size(), 2u);
  // Loose thresholds pass.
  const DiffResult pass = run_diff("bright.exr ref.exr --max-relmse 0.01 --max-de 5", dir);
  EXPECT_EQ(pass.exit_code, 0) << pass.output;
}

TEST(OchreDiff, BadInputExitsTwoNamingTheProblem) {
  const auto dir = scratch_dir();
  write_rgb_exr(dir / "a.exr", gradient());
  const DiffResult missing = run_diff("a.exr nowhere.exr", dir);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("nowhere.exr"), std::string::npos) << missing.output;

  write_rgb_exr(dir / "small.exr", std::vector<float>(3 * 4 * 4, 0.5f), 4, 4);
  const DiffResult size = run_diff("a.exr small.exr", dir);
  EXPECT_EQ(size.exit_code, 2);
  EXPECT_NE(size.output.find("size mismatch: a.exr is 16x12, small.exr is 4x4"), std::string::npos)
      << size.output;

  // A NaN in the reference would make every metric NaN: refused, naming the pixel. (In the test image it
  // is a finding: the metrics are NaN and fail any threshold.)
  std::vector<float> broken = gradient();
  broken[3 * 17 + 1] = std::numeric_limits<float>::quiet_NaN();
  write_rgb_exr(dir / "nan.exr", broken);
  const DiffResult nan_reference = run_diff("a.exr nan.exr", dir);
  EXPECT_EQ(nan_reference.exit_code, 2) << nan_reference.output;
  EXPECT_NE(nan_reference.output.find("nan.exr: pixel (1, 1) channel G is nan: a reference must be finite"),
            std::string::npos)
      << nan_reference.output;
  const DiffResult nan_test = run_diff("nan.exr a.exr --max-rmse 1", dir);
  EXPECT_EQ(nan_test.exit_code, 4) << nan_test.output;

  EXPECT_EQ(run_diff("a.exr", dir).exit_code, 2);  // usage
  const DiffResult help = run_diff("--help", dir);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--max-de"), std::string::npos) << help.output;
}

}  // namespace
}  // namespace ochre::test::ochre_diff_test
