// RGB -> spectrum upsampling (Jakob & Hanika 2019): the embedded table, round trips of the
// ColorChecker and primaries through spectrum and D65, bounds, continuity, emission.

#include "spectra/rgb_spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

#include "spectra/cie.h"
#include "spectra/color_space.h"
#include "spectra/product_spectrum.h"
#include "spectra/rgb_to_spectrum_table.h"

namespace ochre::rgb_spectrum_test {
namespace {

// Linear Rec.709 colour of a reflectance under D65:
// integral s D65 cmf / integral D65 ybar, then XYZ -> linear Rec.709.
RGB colour_under_d65(const SpectrumPtr& reflectance) {
  return xyz_to_rgb(spectrum_to_xyz(ProductSpectrum(reflectance, d65())), ColorSpace::LinearRec709);
}

RGB decode(int r, int g, int b) {
  return {srgb_decode(r / 255.0f), srgb_decode(g / 255.0f), srgb_decode(b / 255.0f)};
}

// ColorChecker Classic, 8-bit sRGB of the 24 patches (X-Rite / BabelColor values, as tabulated in
// N. Pascale, "RGB coordinates of the Macbeth ColorChecker", BabelColor 2006), row by row.
std::vector<RGB> color_checker() {
  const int srgb[24][3] = {{115, 82, 68},   {194, 150, 130}, {98, 122, 157}, {87, 108, 67},   {133, 128, 177},
                           {103, 189, 170}, {214, 126, 44},  {80, 91, 166},  {193, 90, 99},   {94, 60, 108},
                           {157, 188, 64},  {224, 163, 46},  {56, 61, 150},  {70, 148, 73},   {175, 54, 60},
                           {231, 199, 31},  {187, 86, 149},  {8, 133, 161},  {243, 243, 242}, {200, 200, 200},
                           {160, 160, 160}, {122, 122, 121}, {85, 85, 85},   {52, 52, 52}};
  std::vector<RGB> colours;
  for (const auto& c : srgb) colours.push_back(decode(c[0], c[1], c[2]));
  return colours;
}

struct ErrorStats {
  float max = 0.0f, sum = 0.0f;
  int count = 0;
  void add(const RGB& expected, const RGB& actual) {
    for (int c = 0; c < 3; ++c) {
      const float e = std::abs(expected[c] - actual[c]);
      max = std::max(max, e);
      sum += e;
      ++count;
    }
  }
  float mean() const { return sum / float(count); }
};

TEST(RGBToSpectrumTable, GreysAreExactlyConstant) {
  const auto& table = RGBToSpectrumTable::srgb();
  EXPECT_GE(table.resolution(), 32);
  for (float v : {0.0f, 0.01f, 0.18f, 0.5f, 0.73f, 1.0f}) {
    const auto p = table.lookup({v, v, v});
    EXPECT_EQ(p.c0, 0.0f);
    EXPECT_EQ(p.c1, 0.0f);
    EXPECT_NEAR(p.eval(550.0f), v, 1e-6f);
  }
  // Out-of-range components are clamped to [0, 1].
  const auto clamped = table.lookup({2.0f, 2.0f, 2.0f});
  EXPECT_EQ(clamped.eval(500.0f), 1.0f);
}

TEST(RGBAlbedoSpectrum, RoundTripThroughSpectrumAndD65) {
  std::vector<RGB> chromatic;
  for (const RGB& c : color_checker())
    if (!(c.r == c.g && c.g == c.b)) chromatic.push_back(c);
  for (RGB p : {RGB{0.9f, 0, 0}, RGB{0, 0.9f, 0}, RGB{0, 0, 0.9f}, RGB{0.9f, 0.9f, 0}, RGB{0, 0.9f, 0.9f},
                RGB{0.9f, 0, 0.9f}, RGB{0.05f, 0.02f, 0.01f}, RGB{0.3f, 0.6f, 0.2f}})
    chromatic.push_back(p);
  ErrorStats colour_stats;
  for (const RGB& c : chromatic) {
    const RGB back = colour_under_d65(std::make_shared<RGBAlbedoSpectrum>(c));
    colour_stats.add(c, back);
    EXPECT_NEAR(back.r, c.r, 2e-3f) << c.r << " " << c.g << " " << c.b;
    EXPECT_NEAR(back.g, c.g, 2e-3f) << c.r << " " << c.g << " " << c.b;
    EXPECT_NEAR(back.b, c.b, 2e-3f) << c.r << " " << c.g << " " << c.b;
  }
  ErrorStats grey_stats;
  for (float v : {0.0f, 0.02f, 0.1f, 0.18f, 0.35f, 0.5f, 0.8f, 0.95f, 1.0f}) {
    const RGB back = colour_under_d65(std::make_shared<RGBAlbedoSpectrum>(RGB{v, v, v}));
    grey_stats.add({v, v, v}, back);
  }
  for (const RGB& c : color_checker())
    if (c.r == c.g && c.g == c.b) grey_stats.add(c, colour_under_d65(std::make_shared<RGBAlbedoSpectrum>(c)));
  std::cout << "[ figures  ] RGB round trip, " << chromatic.size() << " colours: max abs error "
            << colour_stats.max << ", mean " << colour_stats.mean() << "; greys: max " << grey_stats.max
            << "\n";
  EXPECT_LT(colour_stats.mean(), 5e-4f);
  EXPECT_LT(grey_stats.max, 1e-5f);
}

TEST(RGBAlbedoSpectrum, ValuesStayWithinZeroAndOne) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-0.2f, 1.2f);  // includes out-of-range inputs
  std::vector<RGB> colours = color_checker();
  for (int n = 0; n < 300; ++n) colours.push_back({u(rng), u(rng), u(rng)});
  colours.push_back({1.0f, 0.0f, 0.0f});
  colours.push_back({0.0f, 0.0f, 1e-7f});
  for (const RGB& c : colours) {
    const RGBAlbedoSpectrum s(c);
    float max_seen = 0.0f;
    for (int l = 360; l <= 830; ++l) {
      const float v = s.eval(float(l));
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
      max_seen = std::max(max_seen, v);
    }
    EXPECT_GE(s.max_value(), max_seen - 1e-5f);  // eval() rounds in float
    EXPECT_LE(s.max_value(), 1.0f);
  }
}

TEST(RGBAlbedoSpectrum, ContinuousAcrossTheLargestComponentSwitch) {
  // r slightly above or below g selects different sub-tables; the spectra must agree.
  for (float b : {0.05f, 0.2f, 0.45f}) {
    const RGBAlbedoSpectrum red_first({0.5f, 0.4999f, b}), green_first({0.4999f, 0.5f, b});
    for (int l = 360; l <= 830; l += 10)
      EXPECT_NEAR(red_first.eval(float(l)), green_first.eval(float(l)), 2e-3f)
          << "b " << b << " lambda " << l;
  }
}

TEST(RGBUnboundedSpectrum, ScalesBeyondOne) {
  const RGBUnboundedSpectrum grey({3.0f, 3.0f, 3.0f});
  EXPECT_TRUE(grey.is_constant());
  EXPECT_FLOAT_EQ(grey.eval(450.0f), 3.0f);
  EXPECT_EQ(RGBUnboundedSpectrum({0.0f, 0.0f, 0.0f}).eval(500.0f), 0.0f);
  const RGB c{2.0f, 1.0f, 0.5f};
  const RGB back = colour_under_d65(std::make_shared<RGBUnboundedSpectrum>(c));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], c[i], 2e-3f * c[i]) << i;
}

TEST(RGBIlluminantSpectrum, WhiteIsD65) {
  const RGBIlluminantSpectrum white({1.0f, 1.0f, 1.0f});
  for (int l = 360; l <= 830; l += 7) EXPECT_EQ(white.eval(float(l)), d65()->eval(float(l)));
  const auto w = SampledWavelengths::sample_visible(0.37f);
  EXPECT_EQ(white.sample(w), d65()->sample(w));
  const RGB rgb = xyz_to_rgb(spectrum_to_xyz(white), ColorSpace::LinearRec709);
  EXPECT_NEAR(rgb.r, 1.0f, 1e-5f);
  EXPECT_NEAR(rgb.g, 1.0f, 1e-5f);
  EXPECT_NEAR(rgb.b, 1.0f, 1e-5f);
  EXPECT_NEAR(spectrum_to_xyz(white).y, 1.0f, 1e-6f);
}

TEST(RGBIlluminantSpectrum, EmissionHasTheRequestedColour) {
  for (RGB c : {RGB{0.5f, 0.2f, 0.1f}, RGB{4.0f, 4.0f, 1.0f}, RGB{0.1f, 0.3f, 2.0f}}) {
    const RGBIlluminantSpectrum light(c);
    const RGB back = xyz_to_rgb(spectrum_to_xyz(light), ColorSpace::LinearRec709);
    const float m = std::max({c.r, c.g, c.b});
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], c[i], 2e-3f * m) << i;
    EXPECT_GE(light.max_value(), light.eval(600.0f));
  }
}

}  // namespace
}  // namespace ochre::rgb_spectrum_test
