// Pixel filters by filter importance sampling (renderer/film/pixel_filter.h, docs/scene-format.md, film): the
// default box leaves the sample positions as they are (images of existing scenes keep their bits), a wider
// box spreads them uniformly, and the gaussian draws them with Mitsuba 3's windowed gaussian density.
#include "renderer/film/pixel_filter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ochre::pixel_filter_test {
namespace {

TEST(PixelFilter, PixelBoxKeepsThePositionBitForBit) {
  const PixelFilter box = PixelFilter::box();
  for (float u : {0.0f, 0.123456789f, 0.5f, 0.99999994f}) {
    const Vec2 p = box.sample({u, 1.0f - u});
    EXPECT_EQ(p.x, u);
    EXPECT_EQ(p.y, 1.0f - u);
  }
}

TEST(PixelFilter, WiderBoxIsUniformAroundThePixelCentre) {
  const PixelFilter box = PixelFilter::box(1.5f);
  EXPECT_FLOAT_EQ(box.sample({0.0f, 0.5f}).x, -1.0f);
  EXPECT_FLOAT_EQ(box.sample({0.0f, 0.5f}).y, 0.5f);
  EXPECT_FLOAT_EQ(box.sample({0.75f, 0.25f}).x, 1.25f);
}

// Moments of the windowed gaussian max(0, exp(-x^2 / (2 s^2)) - exp(-8)) on [-4 s, 4 s] by quadrature.
void windowed_gaussian_moments(double s, double& mean_abs, double& variance) {
  double w = 0.0, m1 = 0.0, m2 = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = (2.0 * (i + 0.5) / n - 1.0) * 4.0 * s;
    const double f = std::max(0.0, std::exp(-x * x / (2 * s * s)) - std::exp(-8.0));
    w += f;
    m1 += f * std::abs(x);
    m2 += f * x * x;
  }
  mean_abs = m1 / w;
  variance = m2 / w;
}

TEST(PixelFilter, GaussianDrawsPositionsWithTheFilterDensity) {
  for (float stddev : {0.5f, 1.0f}) {
    const PixelFilter g = PixelFilter::gaussian(stddev);
    EXPECT_FLOAT_EQ(g.radius(), 4.0f * stddev);
    // A stratified sweep of u: the moments of the offsets from the pixel centre are the density's.
    const int n = 1 << 16;
    double mean = 0.0, mean_abs = 0.0, variance = 0.0, largest = 0.0;
    for (int i = 0; i < n; ++i) {
      const double x = g.sample({(i + 0.5f) / n, 0.5f}).x - 0.5;
      mean += x / n;
      mean_abs += std::abs(x) / n;
      variance += x * x / n;
      largest = std::max(largest, std::abs(x));
    }
    double expected_abs = 0.0, expected_variance = 0.0;
    windowed_gaussian_moments(stddev, expected_abs, expected_variance);
    EXPECT_NEAR(mean, 0.0, 1e-4);
    EXPECT_NEAR(mean_abs / expected_abs, 1.0, 1e-3) << stddev;
    EXPECT_NEAR(variance / expected_variance, 1.0, 1e-3) << stddev;
    EXPECT_LE(largest, 4.0 * stddev);
    EXPECT_NEAR(g.sample({0.5f, 0.5f}).y, 0.5f, 1e-3f);  // the median is the pixel centre
  }
}

TEST(PixelFilter, BadParametersAreRefused) {
  EXPECT_THROW(PixelFilter::box(0.0f), std::invalid_argument);
  EXPECT_THROW(PixelFilter::gaussian(-1.0f), std::invalid_argument);
  EXPECT_THROW(PixelFilter::gaussian(NAN), std::invalid_argument);
}

}  // namespace
}  // namespace ochre::pixel_filter_test
