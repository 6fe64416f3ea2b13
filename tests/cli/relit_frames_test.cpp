// `ochre render --frames N --relight` (docs/lights.md, "Relit flicker sequences"): a flicker sequence from
// one render, each frame relit with the flames' intensities and colour temperatures at its time. The relit
// frames match the frames rendered one by one (within their noise); options and scenes it cannot serve are
// refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::relit_frames_test {
namespace {

namespace fs = std::filesystem;

// A wall lit by a torch whose intensity flickers, a grease lamp whose colour temperature flickers too, and a
// dim sky. `extra`: more lights.
std::string flicker_scene(const std::string& extra = "") {
  return fmt::format(R"({{
  "camera": {{"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50}},
  "film": {{"resolution": [24, 16]}}, "integrator": {{"spp": 256}},
  "materials": {{"rock": {{"type": "lambert", "color": [0.6, 0.5, 0.4]}}}},
  "lights": [{{"type": "flame", "preset": "torch", "position": [0.3, 1.2, 0.5]}},
             {{"type": "flame", "preset": "grease_lamp", "position": [-0.5, 0.8, 0.4], "scale": 4,
              "flicker": {{"relative_std": 0.3, "cct_std": 150}}}},
             {{"type": "environment", "radiance": 0.02}}{}],
  "shapes": [{{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{{"translate": [0, 1, 0]}}]}}]
}})",
                     extra);
}

double channel_mean(const ExrImage& image, const char* c) {
  return mean_of(exr_channel(image, c));
}

TEST(RelitFrames, AreTheFramesRenderedOneByOne) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", flicker_scene());
  const CommandResult relit =
      run_ochre("render scene.json -o relit.exr --png relit.png --frames 4 --relight", dir);
  ASSERT_EQ(relit.exit_code, 0) << relit.output;
  ASSERT_EQ(run_ochre("render scene.json -o rendered.exr --frames 4 -q", dir).exit_code, 0);
  double brightest = 0, dimmest = 1e30;
  for (int frame = 1; frame <= 4; ++frame) {
    const ExrImage a = read_exr(dir / fmt::format("relit.{:04d}.exr", frame));
    const ExrImage b = read_exr(dir / fmt::format("rendered.{:04d}.exr", frame));
    EXPECT_TRUE(fs::exists(dir / fmt::format("relit.{:04d}.png", frame)));
    EXPECT_EQ(a.string_attributes.at("ochre.frame"), std::to_string(frame));
    EXPECT_EQ(a.string_attributes.at("ochre.lightGroups"), "flame1,flame2,other") << "a group per flame";
    for (const char* c : {"R", "G", "B"})
      EXPECT_NEAR(channel_mean(a, c) / channel_mean(b, c), 1.0, 0.01) << "frame " << frame << " " << c;
    brightest = std::max(brightest, channel_mean(b, "G"));
    dimmest = std::min(dimmest, channel_mean(b, "G"));
    // The lamp's colour temperature flickers: its group gets spectral bins (16 by default).
    EXPECT_NE(a.find_channel("group.flame2.374,687500nm.R"), nullptr);
  }
  EXPECT_GT(brightest / dimmest, 1.05) << "the frames flicker (else the test shows nothing)";
  // One render, not four.
  EXPECT_NE(relit.output.find("the flames at their mean"), std::string::npos) << relit.output;
}

TEST(RelitFrames, WhatCannotBeRelitIsRefusedOrSaid) {
  const fs::path dir = scratch_dir();
  write_text(dir / "scene.json", flicker_scene());
  const struct {
    std::string args, expected;
  } cases[] = {
      {"--relight", "--relight: only with --frames N"},
      {"--frames 1 --part 0/2 --relight", "--part: not with --relight"},
      {"--frames 2 --relight --polarization-png p.png", "--relight: no polarization image"},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_ochre("render scene.json -o out.exr " + c.args, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.0001.exr")) << c.args;
  }
  // A flame that shares its group with another light cannot flicker on its own.
  write_text(
      dir / "shared.json",
      flicker_scene(R"(, {"type": "point", "position": [1, 2, 1], "intensity": 1, "group": "flame2"})"));
  const CommandResult shared = run_ochre("render shared.json -o out.exr --frames 2 --relight", dir);
  EXPECT_EQ(shared.exit_code, 2) << shared.output;
  EXPECT_NE(shared.output.find("flame 2 shares its light group 'flame2' with other lights"),
            std::string::npos)
      << shared.output;
  // No flames, nothing to relight.
  write_text(dir / "still.json", R"({"film": {"resolution": [4, 4]}, "integrator": {"spp": 1},
    "materials": {"m": {"type": "lambert"}}, "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
    "lights": [{"type": "environment", "radiance": 1}]})");
  const CommandResult still = run_ochre("render still.json -o out.exr --frames 2 --relight", dir);
  EXPECT_EQ(still.exit_code, 2);
  EXPECT_NE(still.output.find("has no flames"), std::string::npos) << still.output;
  EXPECT_FALSE(fs::exists(dir / "out.0001.exr"));
  // A flame that moves: relit at its mean position, and said.
  write_text(dir / "moving.json", flicker_scene());
  std::string text = flicker_scene();
  text.replace(text.find(R"("cct_std": 150)"), 14, R"("cct_std": 150, "position_std": 0.02)");
  write_text(dir / "moving.json", text);
  const CommandResult moving = run_ochre("render moving.json -o moving.exr --frames 2 --relight -q", dir);
  EXPECT_EQ(moving.exit_code, 0) << moving.output;
  EXPECT_NE(moving.output.find("warning: --relight: flame 2 (group 'flame2') also moves"), std::string::npos)
      << moving.output;
}

}  // namespace
}  // namespace ochre::test::relit_frames_test
