// The default scene, a painted cave (scenes/default/), and its capture modes: each renders deterministically
// (the same bits with 1 and 2 threads), the presets select the documented quality (the final preset's
// subdivision level), the capture modes differ the way their lights say (the crossed analyzer removes the
// film's glare), and the display white balance that the torch-lit default uses. Every render names its PNG
// too: without --png the scene's own `output.png` would be written next to the scene, into the source tree.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::cave_scene_test {
namespace {

namespace fs = std::filesystem;

fs::path capture(const std::string& name) {
  return source_dir() / "scenes/default" / (name + ".json");
}

std::vector<float> channel(const fs::path& exr, const char* name) {
  return *read_exr(exr).find_channel(name);
}

double mean(const std::vector<float>& values) {
  double sum = 0;
  for (float v : values) sum += v;
  return sum / double(values.size());
}

TEST(CaveScene, EveryCaptureModeRendersTheSameBitsOnOneAndTwoThreads) {
  for (const char* mode : {"default", "flash", "cross_polarized", "raking", "infrared"}) {
    const fs::path dir = scratch_dir();
    for (int threads : {1, 2}) {
      const CommandResult r = run_ochre(
          fmt::format("render '{}' -o t{}.exr --png t{}.png -q --resolution 32x18 --spp 2 --threads {}",
                      capture(mode).string(), threads, threads, threads),
          dir);
      ASSERT_EQ(r.exit_code, 0) << mode << "\n" << r.output;
    }
    for (const char* c : {"R", "G", "B"})
      EXPECT_EQ(channel(dir / "t1.exr", c), channel(dir / "t2.exr", c)) << mode;
    EXPECT_GT(mean(channel(dir / "t1.exr", "G")), 0.0) << mode;
  }
}

TEST(CaveScene, PresetsChooseTheSubdivisionLevel) {
  const fs::path dir = scratch_dir();
  // Fast (as written): level 3 of 2400 control quads = 307 200 triangles; final: level 4 = 1 228 800.
  CommandResult r =
      run_ochre(fmt::format("render '{}' -o fast.exr --png fast.png --resolution 8x8 --spp 1 --preset fast",
                            capture("default").string()),
                dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 meshes (307200 triangles)"), std::string::npos) << r.output;
  r = run_ochre(
      fmt::format("render '{}' -o final.exr --png final.png --resolution 8x8 --spp 1 --preset final",
                  capture("default").string()),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 meshes (1228800 triangles)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("8x8, 1 spp, max depth 6"), std::string::npos) << r.output;  // --spp overrides 128
}

TEST(CaveScene, CrossedAnalyzerRemovesTheGlareOfTheDampFilm) {
  const fs::path dir = scratch_dir();
  for (const char* mode : {"flash", "cross_polarized"}) {
    const CommandResult r =
        run_ochre(fmt::format("render '{0}' -o {1}.exr --png {1}.png -q --resolution 48x27 --spp 8",
                              capture(mode).string(), mode),
                  dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  // Depolarized light passes the analyzer at half its power; the glare, polarized by the flash's filter
  // and kept by the specular film, is blocked. Without glare the crossed image would be half the flash one
  // (plus the flash's own polarizer, which halves it too: a quarter); the glare makes it less.
  const double flash = mean(channel(dir / "flash.exr", "G")),
               crossed = mean(channel(dir / "cross_polarized.exr", "G"));
  EXPECT_LT(crossed, 0.25 * flash);
  EXPECT_GT(crossed, 0.1 * flash);
}

// output.white_balance: a grey card under a 1900 K sky is orange in the display image unless balanced
// to 1900 K, then grey; the EXR is the same either way.
TEST(WhiteBalance, BalancesTheDisplayImageOnly) {
  const fs::path dir = scratch_dir();
  auto scene = [](const std::string& balance) {
    return R"({"camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 3]}, "film": {"resolution": [4, 4]},
      "integrator": {"spp": 1024, "max_depth": 1},
      "output": {)" +
           balance + R"("exposure": 0},
      "materials": {"grey": {"type": "lambert", "color": 0.5}},
      "lights": [{"type": "environment", "radiance": {"blackbody": 1900}}],
      "shapes": [{"type": "plane", "size": [4, 4], "material": "grey"}]})";
  };
  write_text(dir / "plain.json", scene(""));
  write_text(dir / "balanced.json", scene(R"("white_balance": {"blackbody": 1900}, )"));
  for (const char* name : {"plain", "balanced"})
    ASSERT_EQ(run_ochre(fmt::format("render {0}.json -o {0}.exr --png {0}.png -q", name), dir).exit_code, 0);
  EXPECT_EQ(channel(dir / "plain.exr", "R"), channel(dir / "balanced.exr", "R"));
  int w = 0, h = 0;
  const std::vector<uint8_t> plain = read_png_rgb8(dir / "plain.png", w, h);
  const std::vector<uint8_t> balanced = read_png_rgb8(dir / "balanced.png", w, h);
  // Means over the 16 pixels (the spectral noise of hero wavelengths averages out).
  auto mean_of = [](const std::vector<uint8_t>& p, int c) {
    double sum = 0;
    for (size_t i = size_t(c); i < p.size(); i += 3) sum += p[i];
    return sum / double(p.size() / 3);
  };
  EXPECT_GT(mean_of(plain, 0), mean_of(plain, 2) + 60);  // orange
  EXPECT_NEAR(mean_of(balanced, 0), mean_of(balanced, 1), 1.5);
  EXPECT_NEAR(mean_of(balanced, 2), mean_of(balanced, 1), 1.5);
}

TEST(WhiteBalance, AColourlessIlluminantIsRejected) {
  expect_rejected({"white_balance",
                   scene_text(R"("materials": {"grey": {"type": "lambert"}})",
                              R"("shapes": [{"type": "plane", "material": "grey"}])",
                              R"("output": {"white_balance": {"blackbody": 2000, "scale": 0}},)"),
                   {"scene.json: output.white_balance", "colour"}});
  expect_rejected({"white_balance",
                   scene_text(R"("materials": {"grey": {"type": "lambert"}})",
                              R"("shapes": [{"type": "plane", "material": "grey"}])",
                              R"("output": {"white_balance": "warm"},)"),
                   {"scene.json: output.white_balance"}});
}

}  // namespace
}  // namespace ochre::test::cave_scene_test
