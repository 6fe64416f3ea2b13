// Working colour spaces: names, white mapping, round trips, reference matrices, sRGB transfer.

#include "spectra/color_space.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "spectra/chromatic_adaptation.h"
#include "spectra/cie.h"
#include "spectra/rgb_primaries.h"

namespace ochre::color_space_test {
namespace {

TEST(ColorSpace, ParsesNames) {
  EXPECT_EQ(parse_color_space("rec709"), ColorSpace::LinearRec709);
  EXPECT_EQ(parse_color_space("linear-rec709"), ColorSpace::LinearRec709);
  EXPECT_EQ(parse_color_space("sRGB-linear"), ColorSpace::LinearRec709);
  EXPECT_EQ(parse_color_space("ACEScg"), ColorSpace::ACEScg);
  EXPECT_EQ(parse_color_space(color_space_name(ColorSpace::ACEScg)), ColorSpace::ACEScg);
  EXPECT_EQ(parse_color_space(color_space_name(ColorSpace::LinearRec709)), ColorSpace::LinearRec709);
  try {
    parse_color_space("p3");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown colour space 'p3' (expected one of: rec709, linear-rec709, srgb-linear, acescg)");
  }
}

TEST(ColorSpace, D65IsWhiteInBothSpaces) {
  const XYZ white = spectrum_to_xyz(*d65());
  for (ColorSpace space : {ColorSpace::LinearRec709, ColorSpace::ACEScg}) {
    const RGB rgb = xyz_to_rgb(white, space);
    EXPECT_NEAR(rgb.r, 1.0f, 1e-5f) << color_space_name(space);
    EXPECT_NEAR(rgb.g, 1.0f, 1e-5f) << color_space_name(space);
    EXPECT_NEAR(rgb.b, 1.0f, 1e-5f) << color_space_name(space);
  }
}

TEST(ColorSpace, RoundTrips) {
  const XYZ samples[] = {{0.2f, 0.3f, 0.4f}, {0.9f, 0.5f, 0.05f}, {0.0f, 0.0f, 0.0f}, {1e3f, 2e3f, 5e2f}};
  for (ColorSpace space : {ColorSpace::LinearRec709, ColorSpace::ACEScg})
    for (const XYZ& xyz : samples) {
      const XYZ back = rgb_to_xyz(xyz_to_rgb(xyz, space), space);
      EXPECT_NEAR(back.x, xyz.x, 1e-6f * (1.0f + xyz.x));
      EXPECT_NEAR(back.y, xyz.y, 1e-6f * (1.0f + xyz.y));
      EXPECT_NEAR(back.z, xyz.z, 1e-6f * (1.0f + xyz.z));
    }
  const Mat3 product = rgb_to_xyz_matrix(ColorSpace::ACEScg) * xyz_to_rgb_matrix(ColorSpace::ACEScg);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(product(i, j), i == j ? 1.0 : 0.0, 1e-12);
}

TEST(ColorSpace, Rec709MatchesTheSrgbStandardMatrix) {
  // IEC 61966-2-1:1999 linear sRGB -> XYZ (white xy 0.3127, 0.3290; 4 decimals).
  const double standard[3][3] = {
      {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
  const Mat3& m = rgb_to_xyz_matrix(ColorSpace::LinearRec709);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(m(i, j), standard[i][j], 2e-4) << i << "," << j;
}

TEST(ColorSpace, AcescgOfRec709MatchesTheAcesReference) {
  // Linear sRGB -> ACEScg with Bradford adaptation, as in the OCIO ACES configs
  // (columns are the images of the Rec.709 primaries).
  const double reference[3][3] = {
      {0.613097, 0.339523, 0.047379}, {0.070194, 0.916354, 0.013452}, {0.020616, 0.109570, 0.869815}};
  for (int j = 0; j < 3; ++j) {
    RGB primary;
    primary[j] = 1.0f;
    const RGB aces = xyz_to_rgb(rgb_to_xyz(primary, ColorSpace::LinearRec709), ColorSpace::ACEScg);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(aces[i], reference[i][j], 5e-4) << i << "," << j;
  }
}

TEST(ColorSpace, BradfordMapsWhiteToWhite) {
  const Array3d d65 = xy_to_xyz({0.3127, 0.3290}), d50 = xy_to_xyz({0.3457, 0.3585});
  const Array3d mapped = bradford_adaptation(d65, d50) * d65;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(mapped[i], d50[i], 1e-12);
  // Lindbloom's D65 -> D50 Bradford matrix, first row: 1.0478112 0.0228866 -0.0501270.
  const Mat3 m = bradford_adaptation(xy_to_xyz({0.31271, 0.32902}), xy_to_xyz({0.34567, 0.35850}));
  EXPECT_NEAR(m(0, 0), 1.0478112, 2e-4);
  EXPECT_NEAR(m(0, 1), 0.0228866, 2e-4);
  EXPECT_NEAR(m(0, 2), -0.0501270, 2e-4);
}

TEST(ColorSpace, SrgbTransferFunction) {
  EXPECT_FLOAT_EQ(srgb_encode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgb_encode(1.0f), 1.0f);
  EXPECT_NEAR(srgb_encode(0.0031308f), 0.04045f, 1e-6f);  // both segments meet here
  EXPECT_NEAR(srgb_encode(0.18f), 0.461356f, 1e-5f);
  EXPECT_NEAR(srgb_decode(0.5f), 0.214041f, 1e-6f);
  EXPECT_FLOAT_EQ(srgb_encode(-0.18f), -srgb_encode(0.18f));
  for (float v = 0.0f; v <= 1.5f; v += 0.01f) EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 2e-6f * (1.0f + v));
}

}  // namespace
}  // namespace ochre::color_space_test
