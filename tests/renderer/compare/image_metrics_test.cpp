// Image comparison metrics (renderer/compare/image_metrics.h) on hand-made images with exact expected values,
// and CIEDE2000 (spectra/ciede2000.h) against the published test data of Sharma, Wu, Dalal 2005.
#include "renderer/compare/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/image/display_image.h"
#include "spectra/ciede2000.h"
#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::image_metrics_test {
namespace {

struct Ciede2000Pair {
  Lab first, second;
  double de00;
};

// Table 1 of G. Sharma, W. Wu, E. N. Dalal, Color Res. Appl. 30(1), 2005: all 34 pairs.
const Ciede2000Pair kSharmaPairs[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
};

TEST(Ciede2000, SharmaWuDalalPublishedPairs) {
  int index = 1;
  for (const Ciede2000Pair& pair : kSharmaPairs) {
    // The paper prints dE00 rounded to 4 decimals.
    EXPECT_NEAR(ciede2000(pair.first, pair.second), pair.de00, 1e-4) << "pair " << index;
    EXPECT_NEAR(ciede2000(pair.second, pair.first), pair.de00, 1e-4) << "pair " << index << " swapped";
    ++index;
  }
}

TEST(Ciede2000, IdenticalColoursAndPureLightness) {
  EXPECT_EQ(ciede2000({40, 10, -20}, {40, 10, -20}), 0.0);
  // Achromatic pair with mean L = 50: S_L = 1, so dE00 = |dL|.
  EXPECT_NEAR(ciede2000({0, 0, 0}, {100, 0, 0}), 100.0, 1e-12);
}

TEST(Cielab, WhiteBlackAndSrgbRed) {
  const Lab white = xyz_to_lab(srgb_d65_white(), srgb_d65_white());
  EXPECT_NEAR(white.L, 100.0, 1e-12);
  EXPECT_NEAR(white.a, 0.0, 1e-12);
  EXPECT_NEAR(white.b, 0.0, 1e-12);
  EXPECT_NEAR(xyz_to_lab({0, 0, 0}, srgb_d65_white()).L, 0.0, 1e-12);
  // sRGB red in CIELAB (D65): the textbook (53.24, 80.09, 67.20), computed with more matrix digits
  // than the 4 of IEC 61966-2-1 used here, hence the tolerance.
  const Lab red = xyz_to_lab(linear_srgb_to_xyz(1, 0, 0), srgb_d65_white());
  EXPECT_NEAR(red.L, 53.24, 0.03);
  EXPECT_NEAR(red.a, 80.09, 0.03);
  EXPECT_NEAR(red.b, 67.20, 0.03);
}

RgbImage make_image(int width, int height, std::vector<float> rgb) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb = std::move(rgb);
  return image;
}

DisplayOptions no_ocio() {
  DisplayOptions options;
  options.ocio_config = "none";
  return options;
}

MetricThresholds limits(std::optional<double> rmse, std::optional<double> relmse,
                        std::optional<double> max_error, std::optional<double> max_de) {
  MetricThresholds t;
  t.rmse = rmse;
  t.relmse = relmse;
  t.max_error = max_error;
  t.max_de = max_de;
  return t;
}

TEST(ImageMetrics, IdenticalImagesAreAllZero) {
  const RgbImage a = make_image(2, 1, {0.2f, 0.4f, 0.8f, 3.0f, 0.0f, 1.0f});
  const ImageMetrics m = compare_images(a, a, no_ocio()).metrics;
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.relmse, 0.0);
  EXPECT_EQ(m.max_error, 0.0);
  EXPECT_EQ(m.mean_de00, 0.0);
  EXPECT_EQ(m.max_de00, 0.0);
}

// Two grey pixels; the test image has G = 0.75 instead of 0.5 in pixel (1, 0): d = 0.25 exactly.
TEST(ImageMetrics, OneChannelOfOnePixel) {
  const RgbImage reference = make_image(2, 1, {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
  const RgbImage test = make_image(2, 1, {0.5f, 0.5f, 0.5f, 0.5f, 0.75f, 0.5f});
  const ImageComparison c = compare_images(test, reference, no_ocio());
  EXPECT_DOUBLE_EQ(c.metrics.rmse, std::sqrt(0.0625 / 6.0));
  EXPECT_DOUBLE_EQ(c.metrics.relmse, 0.0625 / (0.25 + kRelMseEpsilon) / 6.0);
  EXPECT_EQ(c.metrics.max_error, 0.25);
  EXPECT_EQ(c.metrics.max_error_x, 1);
  EXPECT_EQ(c.metrics.max_error_y, 0);
  EXPECT_EQ(c.metrics.max_error_channel, 1);
  EXPECT_EQ(c.maps.abs_luminance[0], 0.0f);
  EXPECT_NEAR(c.maps.abs_luminance[1], 0.25 * 0.7152, 0.25 * 2e-4);  // Rec.709 luminance weight of G
  EXPECT_EQ(c.maps.de00[0], 0.0f);
  EXPECT_GT(c.maps.de00[1], 5.0f);  // a clearly visible green shift
  EXPECT_DOUBLE_EQ(c.metrics.mean_de00, c.maps.de00[1] / 2.0);
  EXPECT_DOUBLE_EQ(c.metrics.max_de00, c.maps.de00[1]);
}

// Black reference: relMSE divides by epsilon only. White vs black on display: dE00 = 100 exactly.
TEST(ImageMetrics, BlackReferenceAndWhiteVersusBlack) {
  const RgbImage reference = make_image(1, 2, {0, 0, 0, 0, 0, 0});
  const RgbImage test = make_image(1, 2, {1, 1, 1, 0, 0, 0});
  const ImageComparison c = compare_images(test, reference, no_ocio());
  EXPECT_DOUBLE_EQ(c.metrics.rmse, std::sqrt(3.0 / 6.0));
  EXPECT_DOUBLE_EQ(c.metrics.relmse, 3.0 / kRelMseEpsilon / 6.0);
  EXPECT_EQ(c.metrics.max_error, 1.0);
  EXPECT_EQ(c.metrics.max_error_channel, 0);  // first of the equal maxima
  EXPECT_NEAR(c.maps.de00[0], 100.0, 1e-4);
  EXPECT_NEAR(c.metrics.mean_de00, 50.0, 1e-4);
}

TEST(ImageMetrics, DisplayDe00ClampsLikeTheDisplayImage) {
  // Above 1.0 the no-OCIO display clamps: 2.0 and 5.0 look the same, 0 dE00, but RMSE sees it.
  const ImageComparison c =
      compare_images(make_image(1, 1, {5, 5, 5}), make_image(1, 1, {2, 2, 2}), no_ocio());
  EXPECT_EQ(c.metrics.mean_de00, 0.0);
  EXPECT_DOUBLE_EQ(c.metrics.rmse, 3.0);
}

TEST(ImageMetrics, NanExceedsEveryThreshold) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const ImageMetrics m =
      compare_images(make_image(1, 1, {nan, 0, 0}), make_image(1, 1, {0, 0, 0}), no_ocio()).metrics;
  EXPECT_TRUE(std::isnan(m.rmse));
  EXPECT_TRUE(std::isnan(m.max_error));
  const auto exceeded = exceeded_thresholds(m, limits(1e9, {}, 1e9, {}));
  ASSERT_EQ(exceeded.size(), 2u);
  EXPECT_NE(exceeded[0].find("rmse"), std::string::npos);
  EXPECT_NE(exceeded[1].find("max-error"), std::string::npos);
}

TEST(ImageMetrics, ThresholdsNameTheMetric) {
  ImageMetrics m;
  m.rmse = 0.5;
  m.relmse = 0.1;
  m.max_error = 2.0;
  m.mean_de00 = 1.5;
  EXPECT_TRUE(exceeded_thresholds(m, {}).empty());
  EXPECT_TRUE(exceeded_thresholds(m, limits(0.5, 0.1, 2.0, 1.5)).empty());
  const auto exceeded = exceeded_thresholds(m, limits(1.0, 0.01, {}, 1.0));
  ASSERT_EQ(exceeded.size(), 2u);
  EXPECT_EQ(exceeded[0], "relmse 0.1 > 0.01");
  EXPECT_EQ(exceeded[1], "mean-de00 1.5 > 1");
}

TEST(ImageMetrics, SizeMismatchAndMissingChannelNameTheFiles) {
  const RgbImage a = make_image(2, 1, std::vector<float>(6, 0.0f));
  const RgbImage b = make_image(1, 2, std::vector<float>(6, 0.0f));
  try {
    check_comparable(a, b, "a.exr", "b.exr");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "size mismatch: a.exr is 2x1, b.exr is 1x2");
  }
  ExrImage exr;
  exr.width = 1;
  exr.height = 1;
  exr.channels = {{"B", {0.f}}, {"G", {0.f}}, {"Y", {0.f}}};
  try {
    rgb_from_exr(exr, "luma.exr");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("luma.exr: no channel 'R'"), std::string::npos) << e.what();
  }
}

// CIELAB L* of an 8-bit sRGB colour.
double lightness(const std::array<std::uint8_t, 3>& c) {
  const auto lin = [](std::uint8_t v) { return static_cast<double>(srgb_decode(v / 255.0f)); };
  return xyz_to_lab(linear_srgb_to_xyz(lin(c[0]), lin(c[1]), lin(c[2])), srgb_d65_white()).L;
}

TEST(Heatmap, RampIsWhiteToRedWithDecreasingLightness) {
  EXPECT_EQ(heatmap_colour(0.0), (std::array<std::uint8_t, 3>{255, 255, 255}));
  EXPECT_EQ(heatmap_colour(1.0), (std::array<std::uint8_t, 3>{165, 0, 20}));
  EXPECT_EQ(heatmap_colour(7.0), heatmap_colour(1.0));
  EXPECT_EQ(heatmap_colour(std::nan("")), heatmap_colour(1.0));
  double previous = lightness(heatmap_colour(0.0));
  for (int i = 1; i <= 255; ++i) {
    const double l = lightness(heatmap_colour(i / 255.0));
    EXPECT_LE(l, previous) << "step " << i;  // every channel is non-increasing along the ramp
    previous = l;
  }
  EXPECT_LT(previous, 40.0);  // dark red: far from the white of no error
}

TEST(Heatmap, PngHoldsTheRamp) {
  const auto path = test::scratch_dir() / "heat.png";
  write_heatmap_png(path, 3, 1, {0.0f, 1.0f, 2.0f}, 2.0);
  int w = 0, h = 0;
  const auto pixels = read_png_rgb8(path, w, h);
  ASSERT_EQ(w, 3);
  ASSERT_EQ(h, 1);
  for (int p = 0; p < 3; ++p) {
    const auto expected = heatmap_colour(p / 2.0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(pixels[3 * p + c], expected[c]) << p << " " << c;
  }
}

}  // namespace
}  // namespace ochre::image_metrics_test
