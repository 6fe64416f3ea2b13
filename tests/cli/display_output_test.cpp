// Display output through OpenColorIO from the command line: the built-in config, the no-OCIO
// fallback, and the ACES cg config of the optional external assets folder (docs/validation.md; skipped
// when the folder is absent).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/cli_runner.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_reader.h"
#include "support/test_paths.h"

namespace ochre::test::display_output_test {
namespace {

const char* kGreyPlane = R"({
  "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
  "film": {"resolution": [8, 8]},
  "integrator": {"spp": 64, "max_depth": 1},
  "materials": {"m": {"type": "lambert", "color": 0.5}},
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}],
  "shapes": [{"type": "plane", "size": [4, 4], "material": "m"}]
})";

std::vector<uint8_t> render_png(const std::string& args, std::string* output = nullptr) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", kGreyPlane);
  const CommandResult r = run_ochre("render scene.json --png out.png " + args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  if (output) *output = r.output;
  int w = 0, h = 0;
  return r.exit_code == 0 ? read_png_rgb8(dir / "out.png", w, h) : std::vector<uint8_t>{};
}

// A 0.5 Lambert plane under a D65 environment of luminance 1 is linear grey 0.5: sRGB code 188.
TEST(DisplayOutput, BuiltinConfigAndFallbackAgree) {
  std::string log;
  const auto builtin = render_png("--ocio-config builtin", &log);
  const auto fallback = render_png("--ocio-config none");
  ASSERT_EQ(builtin.size(), 8u * 8u * 3u);
  ASSERT_EQ(fallback.size(), builtin.size());
  double mean = 0.0;
  for (size_t i = 0; i < builtin.size(); ++i) {
    EXPECT_NEAR(builtin[i], fallback[i], 1) << i;  // same pixels, two transforms
    mean += fallback[i] / static_cast<double>(fallback.size());
  }
  EXPECT_NEAR(mean, 188.0, 2.0);  // per-pixel spectral noise averages out
  EXPECT_NE(log.find("sRGB"), std::string::npos) << log;
}

TEST(DisplayOutput, AcesCgConfigFromShared) {
  OCHRE_REQUIRE_SHARED();
  const auto config = shared_dir() / "assets/ocio/cg-config-v1.0.0_aces-v1.3_ocio-v2.1.ocio";
  std::string log;
  const auto aces = render_png("--ocio-config '" + config.string() + "'", &log);
  ASSERT_EQ(aces.size(), 8u * 8u * 3u);
  // The ACES output transform tone-maps: mid grey 0.5 lands near but below the plain sRGB code.
  for (uint8_t v : aces) {
    EXPECT_GT(v, 120);
    EXPECT_LT(v, 200);
  }
  EXPECT_NE(log.find("cg-config"), std::string::npos) << log;
}

TEST(DisplayOutput, MissingConfigIsBadInput) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", kGreyPlane);
  const CommandResult r =
      run_ochre("render scene.json --png out.png --ocio-config /no/such/config.ocio", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("/no/such/config.ocio"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

}  // namespace
}  // namespace ochre::test::display_output_test

namespace ochre::test::display_output_test {
namespace {

// --colorspace acescg writes AP1 primaries: the same render's pixels are the Rec.709 ones through
// the Rec.709 -> ACEScg matrix, and the header says so.
TEST(ExrOutput, AcesCgWorkingSpace) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [4, 4]}, "integrator": {"spp": 16, "max_depth": 1},
    "materials": {"m": {"type": "lambert", "color": [0.6, 0.3, 0.1]}},
    "lights": [{"type": "environment", "radiance": [1, 1, 1]}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "m"}]})");
  ASSERT_EQ(run_ochre("render scene.json -o rec709.exr", dir).exit_code, 0);
  ASSERT_EQ(run_ochre("render scene.json -o acescg.exr --colorspace acescg", dir).exit_code, 0);
  const ExrImage a = read_exr(dir / "rec709.exr"), b = read_exr(dir / "acescg.exr");
  ASSERT_TRUE(b.chromaticities.has_value());
  EXPECT_NEAR(b.chromaticities->red[0], 0.713f, 1e-3f);  // AP1 red x
  EXPECT_NEAR(b.chromaticities->white[0], 0.32168f, 1e-4f);
  ASSERT_TRUE(a.chromaticities.has_value());
  EXPECT_NEAR(a.chromaticities->red[0], 0.64f, 1e-3f);
  // Rec.709 -> ACEScg (Bradford D65 -> ACES white), rows as in the OCIO reference.
  const double m[3][3] = {{0.6131, 0.3395, 0.0474}, {0.0702, 0.9164, 0.0134}, {0.0206, 0.1096, 0.8698}};
  const char* names[3] = {"R", "G", "B"};
  for (size_t i = 0; i < 16; ++i)
    for (int r = 0; r < 3; ++r) {
      double expected = 0.0;
      for (int c = 0; c < 3; ++c) expected += m[r][c] * (*a.find_channel(names[c]))[i];
      EXPECT_NEAR((*b.find_channel(names[r]))[i], expected, 1e-3) << i << " " << r;
    }
}

}  // namespace
}  // namespace ochre::test::display_output_test

namespace ochre::test::display_output_test {
namespace {

// --aovs adds first-hit layers: a 0.5 Lambert plane seen straight down from 5 units has albedo 0.5,
// normal +z, depth 5 and spp samples per pixel.
TEST(ExrOutput, AovLayers) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [4, 4]}, "integrator": {"spp": 8, "max_depth": 1},
    "materials": {"m": {"type": "lambert", "color": 0.5}},
    "lights": [{"type": "environment", "radiance": 1}],
    "shapes": [{"type": "plane", "size": [4, 4], "material": "m"}]})");
  ASSERT_EQ(run_ochre("render scene.json -o out.exr --aovs", dir).exit_code, 0);
  const ExrImage exr = read_exr(dir / "out.exr");
  for (const char* name :
       {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z", "samples.Y"})
    ASSERT_NE(exr.find_channel(name), nullptr) << name;
  for (size_t i = 0; i < 16; ++i) {
    // Albedo: grey 0.5 under D65, through the spectral estimator (4 wavelengths x 8 samples).
    EXPECT_NEAR((*exr.find_channel("albedo.G"))[i], 0.5, 0.05);
    EXPECT_NEAR((*exr.find_channel("normal.Z"))[i], 1.0, 1e-6);
    EXPECT_NEAR((*exr.find_channel("normal.X"))[i], 0.0, 1e-6);
    EXPECT_NEAR((*exr.find_channel("depth.Z"))[i], 5.0, 1e-5);
    EXPECT_EQ((*exr.find_channel("samples.Y"))[i], 8.0f);
  }
  // Without the flag, no AOV layer is written (no cost a scene does not need).
  ASSERT_EQ(run_ochre("render scene.json -o plain.exr", dir).exit_code, 0);
  EXPECT_EQ(read_exr(dir / "plain.exr").find_channel("depth.Z"), nullptr);
}

}  // namespace
}  // namespace ochre::test::display_output_test

namespace ochre::test::display_output_test {
namespace {

// --spectral-bins writes the Fichet et al. layout: S0.<centre>nm channels with a decimal comma and
// the layout attributes. The camera sees a constant environment of radiance 2: every bin holds 2.
TEST(ExrOutput, SpectralLayers) {
  const auto dir = scratch_dir();
  write_text(dir / "scene.json", R"({
    "camera": {"type": "orthographic", "size": 2, "eye": [0, 0, 5], "target": [0, 0, 0]},
    "film": {"resolution": [8, 8]}, "integrator": {"spp": 512},
    "materials": {"m": {"type": "lambert"}},
    "lights": [{"type": "environment", "radiance": 2}],
    "shapes": [{"type": "disk", "radius": 0.001, "material": "m", "transform": [{"translate": [0, 0, -100]}]}],
    "output": {"spectral_range": [400, 720]}})");
  const CommandResult r = run_ochre("render scene.json -o out.exr --spectral-bins 16", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const ExrImage exr = read_exr(dir / "out.exr");
  EXPECT_EQ(exr.string_attributes.at("spectralLayoutVersion"), "1.0");
  EXPECT_EQ(exr.string_attributes.at("emissiveUnits"), "W.m^-2.sr^-1");
  ASSERT_NE(exr.find_channel("S0.410,000000nm"), nullptr);
  ASSERT_NE(exr.find_channel("S0.710,000000nm"), nullptr);
  EXPECT_EQ(exr.find_channel("S0.390,000000nm"), nullptr);
  for (int b = 0; b < 16; ++b) {
    const std::string name = fmt::format("S0.{},000000nm", 410 + 20 * b);
    const std::vector<float>* channel = exr.find_channel(name);
    ASSERT_NE(channel, nullptr) << name;
    double mean = 0.0;
    for (float v : *channel) mean += v / 64.0;
    EXPECT_NEAR(mean, 2.0, 0.06) << name;
  }
}

}  // namespace
}  // namespace ochre::test::display_output_test
