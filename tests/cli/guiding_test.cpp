// Path guiding (integrator.guiding, docs/architecture.md#path-guiding): scattering samples a learned
// histogram of incident light as well as the BSDF, weighted by the mixture's density. Whatever the guide
// learned, the image is the same closed-form one.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "cli/bad_scene.h"
#include "cli/cli_runner.h"
#include "cli/point_light_and_sky.h"
#include "cli/render_probe.h"
#include "support/test_paths.h"

namespace ochre::test::guiding_test {
namespace {

// A Lambert sphere in a constant environment of radiance 1 renders its albedo, here with every bounce
// guided (the guide learns the environment from noisy records, so its density is far from the cosine's).
TEST(Guiding, WhiteFurnaceRendersAlbedoTimesL) {
  const LuminanceImage img = render_luminance(R"({
    "camera": {"type": "orthographic", "size": 3, "eye": [0, 0, 10], "target": [0, 0, 0]},
    "film": {"resolution": [48, 48]},
    "integrator": {"spp": 256, "max_depth": 100, "rr_depth": 100, "guiding": "on"},
    "materials": {"m": {"type": "lambert", "color": 0.5}},
    "lights": [{"type": "environment", "radiance": 1.0}],
    "shapes": [{"type": "sphere", "radius": 1, "subdivisions": 256, "material": "m"}]
  })");
  ASSERT_EQ(img.width, 48);
  const double sphere = img.mean(16, 16, 32, 32);
  std::printf("guided furnace, albedo 0.5: sphere Y = %.5f\n", sphere);
  EXPECT_NEAR(sphere, 0.5, 0.005 * 0.5);
}

// The point light and sky over a plane (cli/point_light_and_sky.h), with a second bounce so that guiding
// runs: the sky is found both by light samples and by scattered rays, and both MIS weights use the guided
// density.
TEST(Guiding, PointLightAndSkyOverAPlaneMatchTheClosedForm) {
  const PointLightAndSky r = render_point_light_and_sky(R"("spp": 1024, "max_depth": 2, "guiding": "on")");
  std::printf("guided point light + sky: worst per-pixel relative error %.4f, mean %.5f (expected %.5f)\n",
              r.worst, r.mean, r.expected_mean);
  EXPECT_NEAR(r.mean / r.expected_mean, 1.0, 0.01);
  EXPECT_LT(r.worst, 0.05);
}

// A Lambert sphere under a constant sky, 16x16 pixels, 4 paths each, guided.
std::string guided_sphere(int max_depth) {
  return fmt::format(R"({{
    "camera": {{"type": "orthographic", "size": 3, "eye": [0, 0, 10], "target": [0, 0, 0]}},
    "film": {{"resolution": [16, 16]}},
    "integrator": {{"spp": 4, "max_depth": {}, "guiding": "on"}},
    "materials": {{"m": {{"type": "lambert", "color": 0.5}}}},
    "lights": [{{"type": "environment", "radiance": 1.0}}],
    "shapes": [{{"type": "sphere", "radius": 1, "material": "m"}}]
  }})",
                     max_depth);
}

// The render's summary says what the guide learned; with paths of one vertex there is nothing to guide,
// and the render says so and runs unguided.
TEST(Guiding, SummaryReportsTheGuide) {
  const std::filesystem::path dir = scratch_dir() / "guiding_summary";
  std::filesystem::create_directories(dir);
  write_text(dir / "lit.json", guided_sphere(4));
  const CommandResult lit = run_ochre("render lit.json -o lit.exr", dir);
  ASSERT_EQ(lit.exit_code, 0) << lit.output;
  EXPECT_NE(lit.output.find("path guiding: guided by"), std::string::npos) << lit.output;
  // A tenth of the paths, at least 65536, at most 64 from each pixel of the grid: here 64 from each of 256.
  EXPECT_NE(lit.output.find("cells learned from 16384 paths"), std::string::npos) << lit.output;

  write_text(dir / "one_bounce.json", guided_sphere(1));
  const CommandResult direct = run_ochre("render one_bounce.json -o one_bounce.exr", dir);
  ASSERT_EQ(direct.exit_code, 0) << direct.output;
  EXPECT_NE(direct.output.find("path guiding: nothing to guide"), std::string::npos) << direct.output;
}

// --guiding on asks for the guide on the command line, as integrator.guiding does in the scene; a resumed
// render keeps its checkpoint's guiding and refuses the option.
TEST(Guiding, CommandLineOptionTurnsItOn) {
  const std::filesystem::path dir = scratch_dir() / "guiding_option";
  std::filesystem::create_directories(dir);
  std::string scene = guided_sphere(4);
  scene.replace(scene.find(R"(, "guiding": "on")"), std::string(R"(, "guiding": "on")").size(), "");
  write_text(dir / "plain.json", scene);
  const CommandResult plain = run_ochre("render plain.json -o plain.exr", dir);
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find("path guiding"), std::string::npos) << plain.output;
  const CommandResult guided = run_ochre("render plain.json --guiding on -o guided.exr", dir);
  ASSERT_EQ(guided.exit_code, 0) << guided.output;
  EXPECT_NE(guided.output.find("path guiding: guided by"), std::string::npos) << guided.output;
  const CommandResult wrong = run_ochre("render plain.json --guiding sometimes -o wrong.exr", dir);
  EXPECT_EQ(wrong.exit_code, 2) << wrong.output;
  EXPECT_NE(wrong.output.find("--guiding"), std::string::npos) << wrong.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "wrong.exr"));
}

TEST(Guiding, UnknownSettingIsRejected) {
  expect_rejected({"guiding",
                   scene_with("/integrator/guiding", R"("sometimes")"),
                   {"integrator.guiding", "unknown guiding setting 'sometimes'", "off, on"}});
}

}  // namespace
}  // namespace ochre::test::guiding_test
