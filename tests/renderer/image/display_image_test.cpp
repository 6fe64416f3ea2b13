// Display images: exact 8-bit values of the no-OCIO sRGB path, agreement of the built-in OCIO config
// with it, the ACES cg config's tone mapping, and errors that name the config or the file.

#include "renderer/image/display_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "renderer/image/ocio_display.h"
#include "renderer/util/image_error.h"
#include "support/test_paths.h"

namespace ochre::display_image_test {
namespace {

namespace fs = std::filesystem;

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << text << "' does not contain '" << part << "'";
}

// One pixel per value, grey.
std::vector<float> grey_pixels(const std::vector<float>& values) {
  std::vector<float> rgb;
  for (float v : values) rgb.insert(rgb.end(), {v, v, v});
  return rgb;
}

std::vector<std::uint8_t> to_rgb8(const std::vector<float>& rgb, DisplayOptions options,
                                  DisplayTransformReport* report = nullptr) {
  return to_display_rgb8(static_cast<int>(rgb.size() / 3), 1, rgb, options, report);
}

DisplayOptions options_with_config(const std::string& config, const std::string& working_space = "rec709") {
  DisplayOptions options;
  options.ocio_config = config;
  options.working_space = working_space;
  return options;
}

// Every combination of 0, 1/8, ..., 1 per channel: in range, saturated and neutral colours.
std::vector<float> colour_grid() {
  std::vector<float> rgb;
  for (int r = 0; r <= 8; ++r)
    for (int g = 0; g <= 8; ++g)
      for (int b = 0; b <= 8; ++b) rgb.insert(rgb.end(), {r / 8.0f, g / 8.0f, b / 8.0f});
  return rgb;
}

int max_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  EXPECT_EQ(a.size(), b.size());
  int worst = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

// Sets $OCIO for one test and restores it.
class ScopedOcioVariable {
 public:
  explicit ScopedOcioVariable(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("OCIO")) saved_ = old;
    set(value);
  }
  ~ScopedOcioVariable() { set(saved_); }

 private:
  static void set(const std::optional<std::string>& value) {
    if (value) {
      ::setenv("OCIO", value->c_str(), 1);
    } else {
      ::unsetenv("OCIO");
    }
  }
  std::optional<std::string> saved_;
};

TEST(SrgbTransfer, ExactCodeValues) {
  // IEC 61966-2-1: linear segment below 0.0031308, then 1.055 v^(1/2.4) - 0.055; round to nearest.
  const std::vector<float> linear = {0.0f,   1.0f,       0.5f, 0.0031308f, 0.18f,
                                     0.001f, 0.2158605f, 2.0f, -1.0f,      NAN};
  const std::vector<std::uint8_t> expected = {0, 255, 188, 10, 118, 3, 128, 255, 0, 0};
  const std::vector<std::uint8_t> pixels = to_rgb8(grey_pixels(linear), options_with_config("none"));
  for (size_t i = 0; i < linear.size(); ++i) {
    EXPECT_EQ(int(pixels[3 * i]), int(expected[i])) << "linear " << linear[i];
  }
}

TEST(SrgbTransfer, ExposureScalesLinearValues) {
  DisplayOptions options = options_with_config("none");
  options.exposure_stops = 1.0f;
  EXPECT_EQ(int(to_rgb8(grey_pixels({0.25f}), options)[0]), 188);  // 0.25 * 2 = 0.5
  options.exposure_stops = -2.0f;
  EXPECT_EQ(int(to_rgb8(grey_pixels({2.0f}), options)[0]), 188);
}

TEST(WorkingSpaceConversion, WhiteIsPreservedAndTheRoundTripIsIdentity) {
  std::vector<float> rgb = {1.0f, 1.0f, 1.0f, 0.2f, 0.5f, 0.9f};
  convert_working_space(rgb, ColorSpace::LinearRec709, ColorSpace::ACEScg);
  EXPECT_NEAR(rgb[0], 1.0f, 1e-6f);
  EXPECT_NEAR(rgb[1], 1.0f, 1e-6f);
  EXPECT_NEAR(rgb[2], 1.0f, 1e-6f);
  convert_working_space(rgb, ColorSpace::ACEScg, ColorSpace::LinearRec709);
  EXPECT_NEAR(rgb[3], 0.2f, 1e-6f);
  EXPECT_NEAR(rgb[4], 0.5f, 1e-6f);
  EXPECT_NEAR(rgb[5], 0.9f, 1e-6f);
  // AP1 red in Rec.709: first column of the ACES/OCIO AP1 -> Rec.709 (Bradford) matrix, also written in
  // renderer/ocio/config.ocio. Out of the Rec.709 gamut (negative green and blue). spectra/color_space.h
  // uses the CIE-integrated D65 white, hence the 2e-4 tolerance.
  std::vector<float> red = {1.0f, 0.0f, 0.0f};
  convert_working_space(red, ColorSpace::ACEScg, ColorSpace::LinearRec709);
  EXPECT_NEAR(red[0], 1.7050510f, 2e-4f);
  EXPECT_NEAR(red[1], -0.1302564f, 2e-4f);
  EXPECT_NEAR(red[2], -0.0240034f, 2e-4f);
}

TEST(SrgbTransfer, AcescgPixelsAreConvertedBeforeEncoding) {
  const std::vector<float> acescg = {1.0f, 1.0f, 1.0f, 0.3f, 0.2f, 0.1f};
  const std::vector<std::uint8_t> pixels = to_rgb8(acescg, options_with_config("none", "acescg"));
  EXPECT_EQ(int(pixels[0]), 255);
  EXPECT_EQ(int(pixels[1]), 255);
  EXPECT_EQ(int(pixels[2]), 255);
  std::vector<float> rec709 = {0.3f, 0.2f, 0.1f};
  convert_working_space(rec709, ColorSpace::ACEScg, ColorSpace::LinearRec709);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(pixels[3 + c], quantize_unorm8(srgb_encode(rec709[c]))) << c;
  EXPECT_THROW(to_rgb8(acescg, options_with_config("none", "srgb")), ImageError);
}

TEST(DisplayPng, NoOcioPngHasTheExactValuesInRowOrder) {
  const fs::path path = test::scratch_dir() / "display.png";
  // 2x2: top row black, 0.5; bottom row 0.0031308, white; channels differ to catch swaps.
  const std::vector<float> rgb = {0.0f,       0.5f, 1.0f, 0.5f, 0.5f, 0.5f,
                                  0.0031308f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f};
  const DisplayTransformReport report = write_display_png(path, 2, 2, rgb, options_with_config("none"));
  EXPECT_EQ(report.description, "built-in sRGB transfer (no OCIO)");
  int width = 0, height = 0;
  const std::vector<std::uint8_t> back = read_png_rgb8(path, width, height);
  EXPECT_EQ(width, 2);
  EXPECT_EQ(height, 2);
  const std::vector<std::uint8_t> expected = {0, 188, 255, 188, 188, 188, 10, 0, 0, 255, 255, 255};
  EXPECT_EQ(back, expected);
}

TEST(DisplayPng, JpegByExtensionAndUnknownExtensionRejected) {
  const fs::path dir = test::scratch_dir();
  const std::vector<float> rgb = grey_pixels({0.5f, 0.5f, 0.5f, 0.5f});
  write_display_image(dir / "display.jpg", 2, 2, rgb, options_with_config("none"));
  int width = 0, height = 0;
  const std::vector<std::uint8_t> back = read_png_rgb8(dir / "display.jpg", width, height);
  EXPECT_EQ(width, 2);
  EXPECT_NEAR(int(back[0]), 188, 2);  // JPEG is lossy
  EXPECT_THROW(write_display_image(dir / "display.tif", 2, 2, rgb, options_with_config("none")), ImageError);
}

TEST(DisplayPng, BadOutputDirectoryOrSizeThrowsNamingTheFileAndWritesNothing) {
  const fs::path dir = test::scratch_dir();
  const fs::path path = dir / "missing" / "display.png";
  try {
    write_display_png(path, 1, 1, grey_pixels({0.5f}), options_with_config("none"));
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), path.string());
  }
  EXPECT_THROW(write_display_png(dir / "a.png", 2, 1, grey_pixels({0.5f}), options_with_config("none")),
               ImageError);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(BuiltinOcioConfig, PassesOcioValidation) {
  EXPECT_NO_THROW(validate_ocio_config("builtin"));
}

TEST(BuiltinOcioConfig, StandardViewMatchesTheNoOcioPathWithinOneCodeValue) {
  const std::vector<float> grid = colour_grid();
  for (const char* space : {"rec709", "acescg"}) {
    DisplayTransformReport report;
    const std::vector<std::uint8_t> ocio = to_rgb8(grid, options_with_config("builtin", space), &report);
    const std::vector<std::uint8_t> plain = to_rgb8(grid, options_with_config("none", space));
    EXPECT_LE(max_difference(ocio, plain), 1) << space;
    EXPECT_TRUE(report.warnings.empty());
    const std::string input = std::string(space) == "rec709" ? "Linear Rec.709 (sRGB)" : "ACEScg";
    EXPECT_EQ(report.description,
              "OCIO config 'built-in': display 'sRGB', view 'Standard' (input colour space '" + input + "')");
  }
}

TEST(BuiltinOcioConfig, RawViewOnlyQuantizes) {
  DisplayOptions options = options_with_config("builtin");
  options.view = "Raw";
  const std::vector<std::uint8_t> pixels = to_rgb8(grey_pixels({0.0f, 0.5f, 1.0f}), options);
  EXPECT_EQ(int(pixels[0]), 0);
  EXPECT_EQ(int(pixels[3]), 128);
  EXPECT_EQ(int(pixels[6]), 255);
}

TEST(BuiltinOcioConfig, IsTheDefaultWhenOcioIsUnset) {
  const ScopedOcioVariable no_ocio(std::nullopt);
  DisplayTransformReport report;
  to_rgb8(grey_pixels({0.5f}), DisplayOptions{}, &report);
  EXPECT_EQ(report.description.rfind("OCIO config 'built-in': display 'sRGB', view 'Standard'", 0), 0u)
      << report.description;
}

TEST(OcioErrors, MissingConfigPathIsNamed) {
  const fs::path missing = test::scratch_dir() / "nowhere.ocio";
  try {
    to_rgb8(grey_pixels({0.5f}), options_with_config(missing.string()));
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    EXPECT_EQ(std::string(error.what()), "OCIO config '" + missing.string() + "' does not exist");
  }
  const ScopedOcioVariable bad_ocio(missing.string());
  try {
    to_rgb8(grey_pixels({0.5f}), DisplayOptions{});
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), missing.string());
    expect_contains(error.what(), "$OCIO");
  }
}

TEST(OcioErrors, UnknownDisplayOrViewListsTheAvailableOnes) {
  DisplayOptions options = options_with_config("builtin");
  options.display = "Cinema";
  try {
    to_rgb8(grey_pixels({0.5f}), options);
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    EXPECT_EQ(std::string(error.what()),
              "OCIO config 'built-in' has no display 'Cinema' (available: 'sRGB')");
  }
  options.display = "sRGB";
  options.view = "Filmic";
  try {
    to_rgb8(grey_pixels({0.5f}), options);
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    EXPECT_EQ(std::string(error.what()),
              "OCIO config 'built-in': display 'sRGB' has no view 'Filmic' (available: 'Standard', 'Raw')");
  }
}

TEST(OcioErrors, InvalidConfigFileIsNamed) {
  const fs::path path = test::scratch_dir() / "broken.ocio";
  std::ofstream(path) << "ocio_profile_version: 2\ncolorspaces: [\n";
  try {
    to_rgb8(grey_pixels({0.5f}), options_with_config(path.string()));
    FAIL() << "should throw";
  } catch (const ImageError& error) {
    expect_contains(error.what(), "cannot load OCIO config '" + path.string() + "'");
  }
}

TEST(OcioInputSpace, UnknownNamesFallBackToSceneLinearWithAWarning) {
  const fs::path path = test::scratch_dir() / "mystery.ocio";
  std::ofstream(path) << "ocio_profile_version: 2\n"
                         "roles:\n  default: mystery\n  scene_linear: mystery\n"
                         "file_rules:\n  - !<Rule> {name: Default, colorspace: default}\n"
                         "displays:\n  Monitor:\n    - !<View> {name: Plain, colorspace: mystery}\n"
                         "colorspaces:\n  - !<ColorSpace>\n    name: mystery\n";
  DisplayTransformReport report;
  const std::vector<std::uint8_t> pixels =
      to_rgb8(grey_pixels({0.5f}), options_with_config(path.string()), &report);
  EXPECT_EQ(int(pixels[0]), 128);
  ASSERT_EQ(report.warnings.size(), 1u);
  expect_contains(report.warnings[0], "scene_linear role 'mystery'");
  EXPECT_EQ(report.description, "OCIO config '" + path.string() +
                                    "': display 'Monitor', view 'Plain' (input colour space 'mystery')");
}

// The ACES cg config (ACES 1.3, OCIO 2.1) that studios use.
fs::path aces_cg_config() {
  return test::shared_dir() / "assets/ocio/cg-config-v1.0.0_aces-v1.3_ocio-v2.1.ocio";
}

TEST(AcesCgConfig, DefaultsAreTheSdrVideoToneMapOnAnSrgbDisplay) {
  OCHRE_REQUIRE_SHARED();
  const OcioDisplay display(aces_cg_config().string(), "", "", ColorSpace::LinearRec709);
  EXPECT_EQ(display.display(), "sRGB - Display");
  EXPECT_EQ(display.view(), "ACES 1.0 - SDR Video");
  EXPECT_EQ(display.input_colour_space(), "Linear Rec.709 (sRGB)");
  EXPECT_EQ(display.input_space(), ColorSpace::LinearRec709);
  EXPECT_TRUE(display.warnings().empty());
  EXPECT_EQ(OcioDisplay(aces_cg_config().string(), "", "", ColorSpace::ACEScg).input_colour_space(),
            "ACEScg");
}

TEST(AcesCgConfig, ToneMappingCompressesHighlights) {
  OCHRE_REQUIRE_SHARED();
  // The ACES 1.0 SDR video view applies the RRT + ODT filmic tone curve: mid grey 0.18 comes out darker
  // than with a plain sRGB encoding (118), scene white 1.0 is NOT display white (it keeps headroom for
  // highlights), and only values far above 1 approach 255.
  DisplayTransformReport report;
  const std::vector<std::uint8_t> pixels = to_rgb8(grey_pixels({0.0f, 0.18f, 1.0f, 16.0f}),
                                                   options_with_config(aces_cg_config().string()), &report);
  EXPECT_EQ(report.description,
            "OCIO config '" + aces_cg_config().string() +
                "': display 'sRGB - Display', view 'ACES 1.0 - SDR Video' (input colour space "
                "'Linear Rec.709 (sRGB)')");
  EXPECT_EQ(int(pixels[0]), 0);
  EXPECT_NEAR(int(pixels[3]), 91, 2);   // display ~0.10 of white: ACES maps 0.18 to ~10 nits of 100
  EXPECT_NEAR(int(pixels[6]), 207, 2);  // not 255: headroom for highlights
  EXPECT_GE(int(pixels[9]), 253);       // 16x scene white saturates
  for (int c = 1; c < 3; ++c) EXPECT_EQ(pixels[3 + c], pixels[3]) << "grey stays neutral";
}

TEST(AcesCgConfig, UntoneMappedViewAgreesWithTheNoOcioPath) {
  OCHRE_REQUIRE_SHARED();
  // Cross-checks our AP1 -> Rec.709 matrix (Bradford) against the ACES config's own transforms.
  const std::vector<float> grid = colour_grid();
  for (const char* space : {"rec709", "acescg"}) {
    DisplayOptions options = options_with_config(aces_cg_config().string(), space);
    options.view = "Un-tone-mapped";
    EXPECT_LE(max_difference(to_rgb8(grid, options), to_rgb8(grid, options_with_config("none", space))), 1)
        << space;
  }
}

}  // namespace
}  // namespace ochre::display_image_test
