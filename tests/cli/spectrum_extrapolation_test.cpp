// A scene's tabulated spectrum outside its table, end to end: "extrapolate": "clamp" (the default) holds
// the end values, "zero" gives no light there, and any other value is bad input naming the field.
// The lamp's table lies wholly beyond the visible range (850-900 nm), so every wavelength ochre samples
// is outside it.
#include <gtest/gtest.h>

#include "cli/cli_runner.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::spectrum_extrapolation_test {
namespace {

std::string scene_with_sky(const std::string& radiance) {
  return R"({"film": {"resolution": [4, 4]}, "integrator": {"spp": 4},
             "camera": {"type": "perspective", "fov": 30, "eye": [0, 0, 5], "target": [0, 0, 0]},
             "materials": {"grey": {"type": "lambert", "color": 0.5}},
             "shapes": [{"type": "sphere", "center": [0, 0, -100], "radius": 0.01, "material": "grey"}],
             "lights": [{"type": "environment", "radiance": )" +
         radiance + "}]}";
}

// Renders the scene and returns its R, G, B channels.
std::vector<std::vector<float>> render_rgb(const std::filesystem::path& dir, const std::string& radiance) {
  write_text(dir / "lamp.csv", "nm,value\n850,2\n900,2\n");
  write_text(dir / "scene.json", scene_with_sky(radiance));
  const CommandResult r = run_ochre("render scene.json -o out.exr -q", dir);
  EXPECT_EQ(r.exit_code, 0) << radiance << "\n" << r.output;
  const ExrImage image = read_exr(dir / "out.exr");
  return {*image.find_channel("R"), *image.find_channel("G"), *image.find_channel("B")};
}

TEST(SpectrumExtrapolation, ClampHoldsTheEndValueZeroGivesNoLight) {
  const auto dir = scratch_dir();
  const auto constant = render_rgb(dir, "2");
  ASSERT_GT(constant[1][0], 1.0f);  // the bright sky is seen directly
  // Held beyond the table: the sky is the constant 2 everywhere ochre samples, by default or on request.
  for (const char* held : {R"({"file": "lamp.csv"})", R"({"file": "lamp.csv", "extrapolate": "clamp"})"}) {
    const auto rgb = render_rgb(dir, held);
    for (int c = 0; c < 3; ++c)
      for (size_t i = 0; i < rgb[c].size(); ++i) EXPECT_NEAR(rgb[c][i], constant[c][i], 1e-5f) << held;
  }
  const auto dark = render_rgb(dir, R"({"file": "lamp.csv", "extrapolate": "zero"})");
  for (const auto& channel : dark)
    for (float v : channel) EXPECT_EQ(v, 0.0f);
}

TEST(SpectrumExtrapolation, UnknownValueIsBadInputNamingTheField) {
  const auto dir = scratch_dir();
  write_text(dir / "lamp.csv", "nm,value\n850,2\n900,2\n");
  write_text(dir / "scene.json", scene_with_sky(R"({"file": "lamp.csv", "extrapolate": "sideways"})"));
  const CommandResult r = run_ochre("render scene.json -o out.exr", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("scene.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lights[0].radiance.extrapolate"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(R"('extrapolate' must be "clamp" or "zero", got "sideways")"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace ochre::test::spectrum_extrapolation_test
