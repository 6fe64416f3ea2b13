// `ochre relight` (docs/lights.md, "Relighting"): a render recombined from its light groups. Unchanged, it is
// the render (display image pixel for pixel); with a group off and another scaled it is the render of the
// scene so changed (within noise); bad changes are refused naming them, nothing written.
#include <fmt/format.h>
#include <gtest/gtest.h>

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
      {"--group torch:cct=1850", "cct changes the group's spectrum, which needs the group's spectral layers"},
      {"--group candle:off", "no light group 'candle' (the render has: torch, lamp, other)"},
      {"--group torch:off --group torch:on", "--group torch: given twice"},
      {"--group torch:scale=-1", "scale must be a finite number >= 0, got '-1'"},
      {"--group torch:scale=nan", "scale must be a finite number >= 0, got 'nan'"},
      {"--group torch:dim", "unknown change 'dim'"},
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

}  // namespace
}  // namespace ochre::test::relight_test
