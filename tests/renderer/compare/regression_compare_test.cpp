// The per-pixel luminance z-test of ochre-regress on synthetic estimates: Sidak level, p-values, equal
// images pass, a 5-sigma shift in one pixel fails, the reference round trip through EXR.
#include "renderer/compare/regression_compare.h"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/image/exr_reader.h"
#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::regression_compare_test {
namespace {

constexpr int kSize = 64;  // 4096 pixels

// A smooth luminance ramp with a variance of the mean that grows with it (as Monte Carlo noise does).
LuminanceEstimate synthetic(double spp) {
  LuminanceEstimate e;
  e.width = kSize;
  e.height = kSize;
  e.samples_per_pixel = spp;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double mean = 0.1 + 0.8 * (x + y) / (2.0 * (kSize - 1));
      e.mean_y.push_back(mean);
      e.variance_of_mean.push_back(0.25 * mean * mean / spp);
    }
  }
  return e;
}

TEST(RegressionCompare, SidakLevelFor4096Pixels) {
  // 1 - 0.99^(1/4096) = 2.4536923e-6.
  EXPECT_NEAR(sidak_pixel_level(0.01, 4096), 2.453692e-6, 1e-11);
  // One pixel: the level itself; the product of the per-pixel acceptances is 1 - alpha.
  EXPECT_DOUBLE_EQ(sidak_pixel_level(0.01, 1), 0.01);
  EXPECT_NEAR(std::pow(1.0 - sidak_pixel_level(0.05, 1000), 1000.0), 0.95, 1e-12);
}

TEST(RegressionCompare, TwoSidedPValues) {
  EXPECT_DOUBLE_EQ(two_sided_p_value(0.0), 1.0);
  EXPECT_NEAR(two_sided_p_value(1.959963985), 0.05, 1e-9);
  EXPECT_NEAR(two_sided_p_value(-2.575829304), 0.01, 1e-9);
  EXPECT_NEAR(two_sided_p_value(5.0), 5.733031e-7, 1e-12);
}

TEST(RegressionCompare, EqualImagesPass) {
  const LuminanceEstimate reference = synthetic(256);
  const LuminanceEstimate test = synthetic(16);
  LuminanceEstimate same_mean = test;
  same_mean.mean_y = reference.mean_y;
  const RegressionResult r = compare_luminance(same_mean, reference);
  EXPECT_TRUE(r.passed());
  EXPECT_EQ(r.failing_pixels, 0u);
  EXPECT_DOUBLE_EQ(r.worst_p, 1.0);
  EXPECT_EQ(r.p_values.size(), 4096u);
  EXPECT_NEAR(r.alpha_pixel, 2.453692e-6, 1e-11);
}

TEST(RegressionCompare, FiveSigmaShiftInOnePixelFails) {
  const LuminanceEstimate reference = synthetic(256);
  LuminanceEstimate test = synthetic(16);
  test.mean_y = reference.mean_y;
  const int px = 17, py = 40;
  const size_t i = static_cast<size_t>(py) * kSize + px;
  // sigma of the difference: test and reference variances of the mean, added.
  const double sigma = std::sqrt(test.variance_of_mean[i] + reference.variance_of_mean[i]);
  test.mean_y[i] += 5.0 * sigma;
  const RegressionResult r = compare_luminance(test, reference);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(r.failing_pixels, 1u);
  EXPECT_EQ(r.worst_x, px);
  EXPECT_EQ(r.worst_y, py);
  EXPECT_NEAR(r.z_scores[i], 5.0, 1e-4);  // the variance floor is ~1e-6 relative
  EXPECT_NEAR(r.worst_p, 5.733031e-7, 1e-9);
  // 4 sigma (p = 6.3e-5) is inside the corrected level: one pixel that far off is expected noise.
  test.mean_y[i] = reference.mean_y[i] + 4.0 * sigma;
  EXPECT_TRUE(compare_luminance(test, reference).passed());
}

TEST(RegressionCompare, ReferenceVarianceBoundsANoiseFreeTestPixel) {
  // A test pixel whose few samples all missed a rare bright path has zero sample variance; the
  // reference's per-sample variance, rescaled to the test's spp, stands in for it.
  const LuminanceEstimate reference = synthetic(256);
  LuminanceEstimate test = synthetic(16);
  test.mean_y = reference.mean_y;
  const size_t i = 100;
  test.variance_of_mean[i] = 0.0;
  const double per_sample = reference.variance_of_mean[i] * 256;
  test.mean_y[i] += 3.0 * std::sqrt(per_sample / 16 + reference.variance_of_mean[i]);
  const RegressionResult r = compare_luminance(test, reference);
  EXPECT_NEAR(r.z_scores[i], 3.0, 1e-4);
  EXPECT_TRUE(r.passed());
}

TEST(RegressionCompare, NonFinitePixelFails) {
  const LuminanceEstimate reference = synthetic(256);
  LuminanceEstimate test = synthetic(16);
  test.mean_y[5] = std::nan("");
  EXPECT_EQ(compare_luminance(test, reference).failing_pixels, 1u);
}

TEST(RegressionCompare, SizeMismatchThrows) {
  LuminanceEstimate small = synthetic(16);
  small.width = 32;
  EXPECT_THROW(compare_luminance(small, synthetic(256)), std::invalid_argument);
}

TEST(RegressionCompare, ReferenceRoundTripsThroughExr) {
  Film film(3, 2);
  for (int s = 0; s < 4; ++s) film.add_sample(1, 0, XYZ{0.1f * s, 0.2f * s, 0.3f * s});
  film.add_sample(2, 1, XYZ{1, 2, 3});
  std::vector<float> rgb(18, 0.25f);
  const auto path = test::scratch_dir() / "ref.exr";
  write_exr(path, make_reference_image(film, rgb, 4));
  const LuminanceEstimate e = luminance_from_reference(read_exr(path), path);
  ASSERT_EQ(e.width, 3);
  ASSERT_EQ(e.height, 2);
  EXPECT_EQ(e.samples_per_pixel, 4.0);
  // Pixel (1, 0): Y = 0, 0.2, 0.4, 0.6: mean 0.3, sample variance 0.0666.., / 4.
  EXPECT_NEAR(e.mean_y[1], 0.3, 1e-6);
  EXPECT_NEAR(e.variance_of_mean[1], (0.2 / 3.0) / 4.0, 1e-6);
  EXPECT_NEAR(e.mean_y[5], 2.0, 1e-6);
  EXPECT_EQ(e.variance_of_mean[5], 0.0);

  ExrImage plain;
  plain.width = 1;
  plain.height = 1;
  plain.channels.emplace_back("R", std::vector<float>{1.0f});
  EXPECT_THROW(luminance_from_reference(plain, "plain.exr"), InputError);
}

TEST(RegressionCompare, PValueImageChannels) {
  const LuminanceEstimate reference = synthetic(256);
  const RegressionResult r = compare_luminance(reference, reference);
  const ExrImage image = p_value_image(r);
  ASSERT_NE(image.find_channel("p.Y"), nullptr);
  ASSERT_NE(image.find_channel("z.Y"), nullptr);
  EXPECT_EQ(image.find_channel("p.Y")->size(), 4096u);
  EXPECT_EQ((*image.find_channel("p.Y"))[0], 1.0f);
}

}  // namespace
}  // namespace ochre::regression_compare_test
