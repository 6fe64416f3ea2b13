// `ochre relight` (docs/lights.md, "Relighting"): a render recombined from its light groups. Unchanged, it is
// the render (display image pixel for pixel); with a group off and another scaled it is the render of the
// scene so changed (within noise); bad changes are refused naming them, nothing written.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "cli/file_test_support.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::relight_test {
namespace {

namespace fs = std::filesystem;

std::string wall(const std::string& torch, double lamp_intensity) {
  return fmt::format(R"({{
  "camera": {{"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50}},
  "film": {{"resolution": [24, 16]}}, "integrator": {{"spp": 512}},
  "output": {{"exposure": -1}},
  "materials": {{"rock": {{"type": "lambert", "color": [0.6, 0.5, 0.4]}}}},
  "lights": [{}
             {{"type": "point", "position": [-1, 2, 1], "intensity": {}, "group": "lamp"}},
             {{"type": "environment", "radiance": 0.05}}],
  "shapes": [{{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{{"translate": [0, 1, 0]}}]}}]
}})",
                     torch, lamp_intensity);
}
const char* kTorch =
    R"({"type": "flame", "preset": "torch", "position": [0.3, 1.2, 0.5], "group": "torch"},)";

fs::path rendered() {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", wall(kTorch, 3));
  const CommandResult r = run_ochre("render scene.json -o render.exr --png render.png -q", dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir;
}

TEST(Relight, UnchangedItIsTheRender) {
  const fs::path dir = rendered();
  const CommandResult r = run_ochre("relight render.exr -o same.exr --png same.png", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "torch:scale=1 lamp:scale=1 other:scale=1")) << r.output;
  const ExrImage a = read_exr(dir / "render.exr"), b = read_exr(dir / "same.exr");
  for (const char* c : {"R", "G", "B"})
    for (size_t i = 0; i < exr_channel(a, c).size(); ++i)
      EXPECT_NEAR(exr_channel(a, c)[i], exr_channel(b, c)[i], 1e-6 * (1 + std::fabs(exr_channel(a, c)[i])))
          << c << i;
  int w = 0, h = 0, w2 = 0, h2 = 0;
  EXPECT_EQ(read_png_rgb8(dir / "render.png", w, h), read_png_rgb8(dir / "same.png", w2, h2))
      << "the render's display transform (exposure -1) is applied";
}

TEST(Relight, AGroupOffAndAnotherScaledIsTheSceneSoChanged) {
  const fs::path dir = rendered();
  ASSERT_EQ(
      run_ochre("relight render.exr --group torch:off --group lamp:scale=2 -o relit.exr -q", dir).exit_code,
      0);
  write_text(dir / "changed.json", wall("", 6));
  ASSERT_EQ(run_ochre("render changed.json -o changed.exr -q --seed 9", dir).exit_code, 0);
  const ExrImage relit = read_exr(dir / "relit.exr"), changed = read_exr(dir / "changed.exr");
  for (const char* c : {"R", "G", "B"}) {
    EXPECT_NEAR(mean_of(exr_channel(relit, c)) / mean_of(exr_channel(changed, c)), 1.0, 0.01) << c;
    // The relit image is its groups' sum, the groups scaled.
    const std::vector<float>& lamp = exr_channel(relit, fmt::format("group.lamp.{}", c));
    const std::vector<float>& torch = exr_channel(relit, fmt::format("group.torch.{}", c));
    for (size_t i = 0; i < lamp.size(); ++i) EXPECT_EQ(torch[i], 0.0f);
  }
  EXPECT_EQ(relit.string_attributes.at("ochre.relight"), "torch:scale=0 lamp:scale=2 other:scale=1");
}

TEST(Relight, BadChangesAreRefusedAndNothingIsWritten) {
  const fs::path dir = rendered();
  const struct {
    std::string args, expected;
  } cases[] = {
      {"--group torch:cct=1850", "light group 'torch' has no spectral bins"},
      {"--group torch:cct=hot", "expected a temperature in kelvin in [500, 100000]"},
      {"--group torch:cct=1800,cct=1900", "one change of spectrum per group"},
      {"--group torch:spectrum=starlight", "starlight"},
      {"--group torch:spectrum=missing.csv", "missing.csv"},
      {"--group candle:off", "no light group 'candle' (the render has: torch, lamp, other)"},
      {"--group torch:off --group torch:on", "--group torch: given twice"},
      {"--group torch:scale=-1", "scale must be a finite number >= 0, got '-1'"},
      {"--group torch:scale=nan", "scale must be a finite number >= 0, got 'nan'"},
      {"--group torch:dim", "unknown change 'dim' (known: scale=S, off, on, cct=T, spectrum=NAME|FILE.csv)"},
      {"--group torch", "expected NAME:scale=S, NAME:off or NAME:on"},
      {"--group lamp:off --view nowhere --png out.png", "nowhere"},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_ochre("relight render.exr -o out.exr " + c.args, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, c.expected)) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.exr")) << c.args;
    EXPECT_FALSE(fs::exists(dir / "out.png")) << c.args;
  }
  const FileSnapshot before = snapshot(dir / "render.exr");
  const CommandResult itself = run_ochre("relight render.exr -o render.exr", dir);
  EXPECT_EQ(itself.exit_code, 2) << itself.output;
  EXPECT_TRUE(snapshot(dir / "render.exr") == before);
  // A render without groups has nothing to relight.
  write_text(dir / "plain.json", R"({"film": {"resolution": [4, 4]}, "integrator": {"spp": 1},
    "materials": {"m": {"type": "lambert"}}, "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
    "lights": [{"type": "environment", "radiance": 1}]})");
  ASSERT_EQ(run_ochre("render plain.json -o plain.exr -q", dir).exit_code, 0);
  const CommandResult plain = run_ochre("relight plain.exr -o out.exr", dir);
  EXPECT_EQ(plain.exit_code, 2);
  EXPECT_TRUE(contains(plain.output, "plain.exr: has no light groups")) << plain.output;
}

// The wall under a torch at `cct` kelvin and a lamp of a 3000 K blackbody, rendered with `bins` spectral bins
// into `name`.exr at a fixed seed.
void render_spectral(const fs::path& dir, const std::string& name, double cct, int bins) {
  const std::string torch = fmt::format(
      R"({{"type": "flame", "preset": "torch", "position": [0.3, 1.2, 0.5], "cct": {}, "group": "torch"}},)",
      cct);
  std::string scene = wall(torch, 3);
  const std::string lamp = R"("intensity": 3, "group": "lamp")";
  scene.replace(scene.find(lamp), lamp.size(),
                R"("intensity": {"blackbody": 3000, "scale": 3}, "group": "lamp")");
  write_text(dir / (name + ".json"), scene);
  const CommandResult r = run_ochre(fmt::format("render {0}.json -o {0}.exr -q --spp 64 --seed 4{1}", name,
                                                bins > 0 ? fmt::format(" --spectral-bins {}", bins) : ""),
                                    dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

// The largest difference between two images' R, G, B relative to the brightest pixel of `b`.
double largest_difference(const ExrImage& a, const ExrImage& b) {
  double largest = 0, brightest = 0;
  for (const char* c : {"R", "G", "B"})
    for (size_t i = 0; i < exr_channel(a, c).size(); ++i) {
      largest = std::max(largest, std::fabs(double(exr_channel(a, c)[i]) - exr_channel(b, c)[i]));
      brightest = std::max(brightest, double(exr_channel(b, c)[i]));
    }
  return largest / brightest;
}

TEST(Relight, SpectralBinsSumToTheGroupAndRecordTheEmission) {
  const fs::path dir = scratch_dir();
  render_spectral(dir, "render", 1700, 8);
  const ExrImage image = read_exr(dir / "render.exr");
  EXPECT_EQ(image.string_attributes.count("ochre.lightGroup.torch.emission"), 1u);
  EXPECT_EQ(image.string_attributes.count("ochre.lightGroup.lamp.emission"), 1u);
  EXPECT_EQ(image.string_attributes.count("ochre.lightGroup.other.emission"), 0u) << "\"other\" has none";
  for (const char* group : {"torch", "lamp", "other"})
    for (const char* c : {"R", "G", "B"}) {
      const std::vector<float>& whole = exr_channel(image, fmt::format("group.{}.{}", group, c));
      std::vector<double> sum(whole.size(), 0.0);
      for (int b = 0; b < 8; ++b) {
        std::string centre = fmt::format("{:.6f}", 360.0f + (b + 0.5f) * 470.0f / 8);
        std::replace(centre.begin(), centre.end(), '.', ',');  // the decimal comma of the spectral layout
        const std::string name = fmt::format("group.{}.{}nm.{}", group, centre, c);
        const std::vector<float>& bin = exr_channel(image, name);
        for (size_t i = 0; i < bin.size(); ++i) sum[i] += bin[i];
      }
      for (size_t i = 0; i < whole.size(); ++i)
        EXPECT_NEAR(sum[i], whole[i], 1e-6 * (1 + whole[i])) << group << c;
    }
}

TEST(Relight, AChangeOfColourTemperatureIsTheSceneSoChanged) {
  const fs::path dir = scratch_dir();
  // The same paths (one seed, lights of the same luminance): the difference is the bins' alone.
  render_spectral(dir, "changed", 2600, 0);
  const ExrImage changed = read_exr(dir / "changed.exr");
  double previous_bias = 1.0;
  for (const int bins : {4, 16, 64}) {
    render_spectral(dir, fmt::format("bins{}", bins), 1700, bins);
    const CommandResult r =
        run_ochre(fmt::format("relight bins{0}.exr --group torch:cct=2600 -o relit{0}.exr -q", bins), dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const ExrImage relit = read_exr(dir / fmt::format("relit{}.exr", bins));
    // The bias, over the image: the ratio of the new emission to the old varies within a bin, which weighs
    // each sample by the bin's mean ratio; per pixel that adds a noise that falls with the samples.
    double bias = 0;
    for (const char* c : {"R", "G", "B"})
      bias = std::max(bias, std::fabs(mean_of(exr_channel(relit, c)) / mean_of(exr_channel(changed, c)) - 1));
    EXPECT_LT(bias, previous_bias) << bins << " bins: the error falls as the bins narrow";
    previous_bias = bias;
    if (bins == 16) {
      EXPECT_LT(bias, 0.01) << "16 bins: each bin weighed per X, Y, Z";
    }
    if (bins == 64) {
      EXPECT_LT(largest_difference(relit, changed), 5e-3) << "64 bins, per pixel";
    }
    // Relit back, it is the render again.
    const CommandResult back =
        run_ochre(fmt::format("relight relit{0}.exr --group torch:cct=1700 -o back{0}.exr -q", bins), dir);
    ASSERT_EQ(back.exit_code, 0) << back.output;
    EXPECT_LT(largest_difference(read_exr(dir / fmt::format("back{}.exr", bins)),
                                 read_exr(dir / fmt::format("bins{}.exr", bins))),
              1e-5);
  }
  EXPECT_LT(previous_bias, 2e-3) << "64 bins";
  // Without bins the change is refused; "other" has no one emission spectrum.
  const CommandResult other = run_ochre("relight bins4.exr --group other:cct=2000 -o x.exr", dir);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_TRUE(contains(other.output, "light group 'other' has no one emission spectrum")) << other.output;
}

// A wall lit by a glowing panel (an emissive rectangle, group "panel") of a blackbody at `kelvin`.
std::string panel_scene(double kelvin) {
  return fmt::format(R"({{
  "camera": {{"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50}},
  "film": {{"resolution": [24, 16]}}, "integrator": {{"spp": 64}},
  "materials": {{"rock": {{"type": "lambert", "color": [0.6, 0.5, 0.4]}},
                "glow": {{"type": "emission", "color": {{"blackbody": {}}}, "strength": 4}}}},
  "shapes": [{{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{{"translate": [0, 1, 0]}}]}},
             {{"type": "plane", "size": [0.6, 0.6], "material": "glow", "light_group": "panel",
              "transform": [{{"rotate": {{"axis": [1, 0, 0], "angle": 90}}}}, {{"translate": [0, 1, 1.5]}}]}}]
}})",
                     kelvin);
}

TEST(Relight, AnEmissiveSurfaceChangesItsColourTemperature) {
  const fs::path dir = scratch_dir();
  write_text(dir / "warm.json", panel_scene(2000));
  write_text(dir / "cold.json", panel_scene(6500));
  ASSERT_EQ(run_ochre("render warm.json -o warm.exr -q --seed 3 --spectral-bins 16", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render cold.json -o cold.exr -q --seed 3", dir).exit_code, 0);
  const ExrImage warm = read_exr(dir / "warm.exr");
  // A material uniform over the surface has one emission spectrum: the group records it.
  EXPECT_EQ(warm.string_attributes.count("ochre.lightGroup.panel.emission"), 1u);
  const CommandResult r = run_ochre("relight warm.exr --group panel:cct=6500 -o relit.exr -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage relit = read_exr(dir / "relit.exr"), cold = read_exr(dir / "cold.exr");
  for (const char* c : {"R", "G", "B"})
    EXPECT_NEAR(mean_of(exr_channel(relit, c)) / mean_of(exr_channel(cold, c)), 1.0, 0.01) << c;
  // The change is large: the warm panel's image is far redder.
  const auto red_over_green = [](const ExrImage& image) {
    return mean_of(exr_channel(image, "R")) / mean_of(exr_channel(image, "G"));
  };
  EXPECT_GT(red_over_green(warm), 1.3 * red_over_green(cold));
}

}  // namespace
}  // namespace ochre::test::relight_test
