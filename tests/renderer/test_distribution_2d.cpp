// Distribution2D: exact per-cell densities, normalisation, sample frequencies against the weights,
// samples inside their cell, zero-weight cells never chosen.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "renderer/distribution_2d.h"

namespace ochre {
namespace {

// 4 columns x 3 rows; row 1 is empty, cell (2, 0) too.
const std::vector<double> kWeights = {1, 2, 0, 5,  //
                                      0, 0, 0, 0,  //
                                      3, 1, 4, 8};
constexpr double kTotal = 24.0;

TEST(Distribution2D, DensityIsWeightOverTotalTimesCellCount) {
  const Distribution2D d(kWeights, 4, 3);
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      EXPECT_NEAR(d.pdf(column, row), kWeights[row * 4 + column] / kTotal * 12.0, 1e-6)
          << column << "," << row;
  // The density of a point is its cell's.
  EXPECT_NEAR(d.pdf(Vec2{0.9f, 0.1f}), 5.0 / kTotal * 12.0, 1e-6);
  EXPECT_NEAR(d.pdf(Vec2{0.55f, 0.99f}), 4.0 / kTotal * 12.0, 1e-6);
}

TEST(Distribution2D, DensityIntegratesToOne) {
  std::vector<double> weights(37 * 11);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 10.0);
  for (double& w : weights) w = uniform(rng);
  const Distribution2D d(weights, 37, 11);
  double integral = 0.0;
  for (int row = 0; row < 11; ++row)
    for (int column = 0; column < 37; ++column) integral += d.pdf(column, row) / (37.0 * 11.0);
  EXPECT_NEAR(integral, 1.0, 1e-5);
}

TEST(Distribution2D, SampleFrequenciesFollowTheWeights) {
  const Distribution2D d(kWeights, 4, 3);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  constexpr int kSamples = 240000;
  std::vector<int> counts(12, 0);
  for (int i = 0; i < kSamples; ++i) {
    const Distribution2D::Sample s = d.sample({uniform(rng), uniform(rng)});
    // The point lies in the returned cell and carries that cell's density.
    ASSERT_GE(s.uv.x, s.column / 4.0f);
    ASSERT_LT(s.uv.x, (s.column + 1) / 4.0f);
    ASSERT_GE(s.uv.y, s.row / 3.0f);
    ASSERT_LT(s.uv.y, (s.row + 1) / 3.0f);
    ASSERT_EQ(s.pdf, d.pdf(s.column, s.row));
    ASSERT_EQ(s.pdf, d.pdf(s.uv));
    ++counts[s.row * 4 + s.column];
  }
  for (int cell = 0; cell < 12; ++cell) {
    const double expected = kWeights[cell] / kTotal * kSamples;
    if (expected == 0.0) {
      EXPECT_EQ(counts[cell], 0) << "cell " << cell;
    } else {
      EXPECT_NEAR(counts[cell], expected, 5.0 * std::sqrt(expected)) << "cell " << cell;  // 5 sigma
    }
  }
}

TEST(Distribution2D, PointsAreUniformInsideTheirCell) {
  // One cell only: u and v must come back as they went in (up to the cell's offset and width).
  const Distribution2D d({0, 0, 0, 1}, 2, 2);
  const Distribution2D::Sample s = d.sample({0.25f, 0.75f});
  EXPECT_EQ(s.column, 1);
  EXPECT_EQ(s.row, 1);
  EXPECT_NEAR(s.uv.x, 0.5f + 0.25f / 2.0f, 1e-6);
  EXPECT_NEAR(s.uv.y, 0.5f + 0.75f / 2.0f, 1e-6);
  EXPECT_FLOAT_EQ(s.pdf, 4.0f);
}

TEST(Distribution2D, AllZeroIsEmptyAndBadSizesThrow) {
  const Distribution2D zero(std::vector<double>(6, 0.0), 3, 2);
  EXPECT_TRUE(zero.empty());
  EXPECT_EQ(zero.pdf(1, 1), 0.0f);
  EXPECT_EQ(zero.sample({0.5f, 0.5f}).pdf, 0.0f);
  EXPECT_THROW(Distribution2D(std::vector<double>(5, 1.0), 3, 2), std::invalid_argument);
  EXPECT_THROW(Distribution2D({}, 0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace ochre
