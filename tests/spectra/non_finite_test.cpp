// NaN and infinities before a table index: nan_safe_clamp is std::clamp except for NaN, finite_or_limit
// replaces the non-finite, and the RGB -> spectrum lookups give finite spectra for any input, with the same
// coefficients as before for every finite colour.

#include "spectra/non_finite.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "spectra/rgb_spectrum.h"
#include "spectra/rgb_to_spectrum_table.h"
#include "support/awkward_floats.h"

namespace ochre::test::non_finite_test {
namespace {

using test::awkward_floats;

std::vector<float> awkward_values() {  // and ordinary ones
  std::vector<float> v = awkward_floats();
  v.insert(v.end(), {0.0f, 0.25f, 0.5f, 1.0f, 2.0f});
  return v;
}

uint32_t bits(float v) {
  return std::bit_cast<uint32_t>(v);
}

TEST(NonFinite, NanSafeClampIsStdClampForEveryNonNanValue) {
  for (float v : awkward_values()) {
    if (std::isnan(v)) continue;
    for (auto [lo, hi] : {std::pair{0.0f, 1.0f}, std::pair{-1.0f, 1.0f}, std::pair{0.0f, kLargest}}) {
      EXPECT_EQ(bits(nan_safe_clamp(v, lo, hi)), bits(std::clamp(v, lo, hi)))
          << v << " in " << lo << ", " << hi;
    }
  }
  EXPECT_EQ(nan_safe_clamp(-0.0f, 0.0f, 1.0f), 0.0f);
  EXPECT_TRUE(std::signbit(nan_safe_clamp(-0.0f, 0.0f, 1.0f)));  // as std::clamp: -0 is not below 0
}

TEST(NonFinite, NanSafeClampMapsNanToTheLowerBound) {
  EXPECT_EQ(nan_safe_clamp(kNaN, 0.0f, 1.0f), 0.0f);
  EXPECT_EQ(nan_safe_clamp(kNaN, -1.0f, 1.0f), -1.0f);
  EXPECT_EQ(nan_safe_clamp(std::nan(""), 0.25, 1.0), 0.25);
  EXPECT_TRUE(std::isnan(std::clamp(kNaN, 0.0f, 1.0f)));  // the defect it exists for
}

TEST(NonFinite, FiniteOrLimitReplacesOnlyNonFiniteValues) {
  EXPECT_EQ(bits(finite_or_limit(kNaN)), bits(0.0f));
  EXPECT_EQ(finite_or_limit(kInf), kLargest);
  EXPECT_EQ(finite_or_limit(-kInf), -kLargest);
  EXPECT_EQ(finite_or_limit(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::max());
  for (float v : awkward_values())
    if (std::isfinite(v)) {
      EXPECT_EQ(bits(finite_or_limit(v)), bits(v)) << v;
    }
}

void expect_finite_reflectance(const RGBSigmoidPolynomial& poly, const RGB& rgb) {
  for (float lambda : {360.0f, 450.0f, 550.0f, 700.0f, 830.0f}) {
    const float v = poly.eval(lambda);
    EXPECT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f)
        << "rgb " << rgb.r << ", " << rgb.g << ", " << rgb.b << " at " << lambda << " nm: " << v;
  }
}

TEST(NonFinite, RgbToSpectrumLookupIsFiniteForEveryInput) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  for (float r : awkward_values())
    for (float g : awkward_values())
      for (float b : {kNaN, kInf, -kInf, 1e30f, 0.0f, 0.5f})
        expect_finite_reflectance(table.lookup({r, g, b}), {r, g, b});
}

TEST(NonFinite, RgbToSpectrumLookupReadsNanAsZero) {
  const RGBToSpectrumTable& table = RGBToSpectrumTable::srgb();
  const RGBSigmoidPolynomial with_nan = table.lookup({0.7f, kNaN, 0.2f}),
                             with_zero = table.lookup({0.7f, 0.0f, 0.2f});
  EXPECT_EQ(with_nan.c0, with_zero.c0);
  EXPECT_EQ(with_nan.c1, with_zero.c1);
  EXPECT_EQ(with_nan.c2, with_zero.c2);
}

TEST(NonFinite, UnboundedSpectraAreFiniteForEveryInput) {
  for (float r : awkward_values())
    for (float g : awkward_values())
      for (float b : {kNaN, kInf, -kInf, 1e30f, 0.0f, 0.5f}) {
        const RGB rgb{r, g, b};
        const UnboundedRGB u = decompose_unbounded(rgb);
        EXPECT_TRUE(std::isfinite(u.scale) && u.scale >= 0.0f) << r << ", " << g << ", " << b;
        expect_finite_reflectance(u.poly, rgb);
        const RGBUnboundedSpectrum unbounded(rgb);
        const RGBIlluminantSpectrum illuminant(rgb);
        for (float lambda : {400.0f, 550.0f, 700.0f}) {
          EXPECT_TRUE(std::isfinite(unbounded.eval(lambda))) << r << ", " << g << ", " << b;
          EXPECT_TRUE(std::isfinite(illuminant.eval(lambda))) << r << ", " << g << ", " << b;
        }
      }
}

TEST(NonFinite, HugeColoursKeepTheirChromaticity) {
  const UnboundedRGB huge = decompose_unbounded({3e38f, 1.5e38f, 0.0f});  // 2 max overflows a float
  const UnboundedRGB small = decompose_unbounded({3.0f, 1.5f, 0.0f});
  EXPECT_EQ(huge.scale, kLargest);
  EXPECT_EQ(huge.poly.c0, small.poly.c0);
  EXPECT_EQ(huge.poly.c1, small.poly.c1);
  EXPECT_EQ(huge.poly.c2, small.poly.c2);
}

// decompose_unbounded computes rgb / (2 max) as (rgb / max) / 2 so that 2 max cannot overflow: the
// polynomial must be the one of the former formula, bit for bit (rendered images do not change).
TEST(NonFinite, UnboundedDecompositionMatchesTheDirectFormula) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> component(0.0f, 1.0f);
  std::uniform_real_distribution<float> exponent(-20.0f, 20.0f);
  for (int i = 0; i < 20000; ++i) {
    const float scale = std::exp2(exponent(rng));
    const RGB rgb{component(rng) * scale, component(rng) * scale, component(rng) * scale};
    const float m = 2.0f * std::max({rgb.r, rgb.g, rgb.b});
    if (m == 0.0f) continue;
    const RGBSigmoidPolynomial direct = RGBToSpectrumTable::srgb().lookup({rgb.r / m, rgb.g / m, rgb.b / m});
    const UnboundedRGB u = decompose_unbounded(rgb);
    ASSERT_EQ(u.scale, m);
    ASSERT_EQ(bits(u.poly.c0), bits(direct.c0)) << rgb.r << ", " << rgb.g << ", " << rgb.b;
    ASSERT_EQ(bits(u.poly.c1), bits(direct.c1));
    ASSERT_EQ(bits(u.poly.c2), bits(direct.c2));
  }
}

}  // namespace
}  // namespace ochre::test::non_finite_test
