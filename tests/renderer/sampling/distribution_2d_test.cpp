// Distribution2D: exact per-cell densities, normalisation, sample frequencies against the weights
// (chi-square on a grid that is not a multiple of the block size), samples inside their cell, zero-weight
// cells and blocks never chosen, the monotone map from u to the point, and a printed micro-benchmark.

#include "renderer/sampling/distribution_2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "materials/core/pcg32.h"
#include "materials/lobes/sampling_check.h"

namespace ochre::distribution_2d_test {
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

// A 37 x 19 grid (blocks of 4: the last block column holds 1 column, the last block row 3 rows) with
// zero-weight cells, one all-zero block (columns 8-11, rows 4-7) and a spike worth ~1/3 of the total.
constexpr int kOddWidth = 37, kOddHeight = 19;
std::vector<double> odd_weights() {
  std::vector<double> w(kOddWidth * kOddHeight);
  Pcg32 rng(3);
  for (int row = 0; row < kOddHeight; ++row)
    for (int column = 0; column < kOddWidth; ++column) {
      double& x = w[row * kOddWidth + column];
      x = 0.5 + 1.5 * rng.next_float();
      if ((row * kOddWidth + column) % 7 == 3) x = 0.0;
      if (column >= 8 && column < 12 && row >= 4 && row < 8) x = 0.0;
    }
  w[13 * kOddWidth + 36] = 400.0;  // in the last (one column wide) block column
  return w;
}

// Upper tail of the chi-square distribution: Q(dof / 2, chi2 / 2).
double chi2_p_value(double chi2, int dof) {
  return regularized_gamma_q(0.5 * dof, 0.5 * chi2);
}

TEST(Distribution2D, OddSizeDensityIsExactAndIntegratesToOne) {
  const std::vector<double> w = odd_weights();
  const Distribution2D d(w, kOddWidth, kOddHeight);
  double total = 0.0;
  for (double x : w) total += x;
  const double cells = kOddWidth * kOddHeight;
  double integral = 0.0;
  for (int row = 0; row < kOddHeight; ++row)
    for (int column = 0; column < kOddWidth; ++column) {
      const double expected = w[row * kOddWidth + column] / total * cells;
      const float pdf = d.pdf(column, row);
      if (expected == 0.0) {
        ASSERT_EQ(pdf, 0.0f) << column << "," << row;
      } else {
        ASSERT_NEAR(pdf, expected, 2e-6 * expected) << column << "," << row;
      }
      // The density of a point is its cell's, at the cell's centre and corners.
      ASSERT_EQ(d.pdf(Vec2{(column + 0.5f) / kOddWidth, (row + 0.5f) / kOddHeight}), pdf);
      ASSERT_EQ(d.pdf(Vec2{static_cast<float>(column) / kOddWidth, static_cast<float>(row) / kOddHeight}),
                d.pdf(d.column_of(static_cast<float>(column) / kOddWidth),
                      d.row_of(static_cast<float>(row) / kOddHeight)));
      ASSERT_EQ(d.pdf_of_key(d.cell_key(column, row)), pdf);
      integral += pdf / cells;
    }
  EXPECT_NEAR(integral, 1.0, 1e-5);
  // Keys are distinct and within key_count().
  std::vector<int> seen(d.key_count(), 0);
  for (int row = 0; row < kOddHeight; ++row)
    for (int column = 0; column < kOddWidth; ++column) {
      const size_t key = d.cell_key(column, row);
      ASSERT_LT(key, d.key_count());
      ASSERT_EQ(seen[key]++, 0) << column << "," << row;
    }
  EXPECT_EQ(d.key_count(), static_cast<size_t>(10 * 5 * 16));
}

TEST(Distribution2D, OddSizeSamplesMatchThePdfChiSquare) {
  const std::vector<double> w = odd_weights();
  const Distribution2D d(w, kOddWidth, kOddHeight);
  constexpr int kSamples = 300000;
  const int cells = kOddWidth * kOddHeight;
  std::vector<double> observed(cells, 0.0);
  Pcg32 rng(21);
  for (int i = 0; i < kSamples; ++i) {
    const Distribution2D::Sample s = d.sample({rng.next_float(), rng.next_float()});
    ASSERT_GE(s.column, 0);
    ASSERT_LT(s.column, kOddWidth);
    ASSERT_GE(s.row, 0);
    ASSERT_LT(s.row, kOddHeight);
    ASSERT_GT(w[s.row * kOddWidth + s.column], 0.0) << "zero-weight cell " << s.column << "," << s.row;
    ASSERT_EQ(s.pdf, d.pdf(s.column, s.row));
    ASSERT_EQ(s.pdf, d.pdf(s.uv));
    ASSERT_EQ(s.key, d.cell_key(s.column, s.row));
    ASSERT_GE(s.uv.x, static_cast<float>(s.column) / kOddWidth);
    ASSERT_LT(s.uv.x, static_cast<float>(s.column + 1) / kOddWidth);
    ASSERT_GE(s.uv.y, static_cast<float>(s.row) / kOddHeight);
    ASSERT_LT(s.uv.y, static_cast<float>(s.row + 1) / kOddHeight);
    observed[s.row * kOddWidth + s.column] += 1.0;
  }
  // Expected counts from pdf() (not from the weights: this checks sample() against pdf()); cells expecting
  // fewer than 5 samples are pooled.
  double chi2 = 0.0, pooled_expected = 0.0, pooled_observed = 0.0;
  int dof = -1;
  for (int cell = 0; cell < cells; ++cell) {
    const double expected = d.pdf(cell % kOddWidth, cell / kOddWidth) / cells * kSamples;
    if (expected == 0.0) {
      ASSERT_EQ(observed[cell], 0.0);
    }
    if (expected < 5.0) {
      pooled_expected += expected;
      pooled_observed += observed[cell];
      continue;
    }
    chi2 += (observed[cell] - expected) * (observed[cell] - expected) / expected;
    ++dof;
  }
  if (pooled_expected > 0.0) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++dof;
  }
  const double p = chi2_p_value(chi2, dof);
  std::printf("[ chi2 ] 37 x 19 blocked distribution: chi2 %.1f, %d dof, p = %.3f\n", chi2, dof, p);
  EXPECT_GT(p, 1e-3);
  // The spike gets its share: 400 of the total weight.
  double total = 0.0;
  for (double x : w) total += x;
  const double spike = 400.0 / total * kSamples;
  EXPECT_NEAR(observed[13 * kOddWidth + 36], spike, 5.0 * std::sqrt(spike));
}

// u values where the inversions change interval: the bounds k / n of the grid's and the blocks' buckets,
// their float neighbours, 0 and the largest float below 1.
std::vector<float> edge_values(std::initializer_list<int> sizes) {
  std::vector<float> u = {0.0f, 0.99999994f, 0.5f};
  for (int n : sizes)
    for (int k = 0; k <= n; ++k) {
      const float b = static_cast<float>(static_cast<double>(k) / n);
      for (float x : {b, std::nextafter(b, 0.0f), std::nextafter(b, 1.0f)})
        if (x >= 0.0f && x < 1.0f) u.push_back(x);
    }
  std::sort(u.begin(), u.end());
  u.erase(std::unique(u.begin(), u.end()), u.end());
  return u;
}

// For a fixed u.y the map from u.x to the point is a CDF inversion at every level: increasing u.x never
// moves the point left (so within a row the column never decreases), which keeps the stratification of
// the sampler's (0,2)-sequence points. The point lies inside its (non-zero) cell at every edge value.
TEST(Distribution2D, MapIsMonotoneAndPointsStayInTheirCellAtEdges) {
  const std::vector<double> w = odd_weights();
  const Distribution2D d(w, kOddWidth, kOddHeight);
  std::vector<float> xs = edge_values({kOddWidth, 10, 2 * kOddWidth});
  for (int k = 0; k < 4000; ++k) xs.push_back(static_cast<float>((k + 0.5) / 4000.0));
  std::sort(xs.begin(), xs.end());
  for (float v : edge_values({kOddHeight, 5})) {
    Distribution2D::Sample previous;
    std::vector<int> last_column_in_row(kOddHeight, -1);
    for (size_t i = 0; i < xs.size(); ++i) {
      const Distribution2D::Sample s = d.sample({xs[i], v});
      ASSERT_GT(w[s.row * kOddWidth + s.column], 0.0) << xs[i] << " " << v;
      ASSERT_GE(s.uv.x, static_cast<float>(s.column) / kOddWidth) << xs[i] << " " << v;
      ASSERT_LT(s.uv.x, static_cast<float>(s.column + 1) / kOddWidth) << xs[i] << " " << v;
      ASSERT_GE(s.uv.y, static_cast<float>(s.row) / kOddHeight) << xs[i] << " " << v;
      ASSERT_LT(s.uv.y, static_cast<float>(s.row + 1) / kOddHeight) << xs[i] << " " << v;
      ASSERT_EQ(d.pdf(s.uv), s.pdf) << xs[i] << " " << v;
      if (i > 0) {
        ASSERT_GE(s.uv.x, previous.uv.x) << xs[i - 1] << " -> " << xs[i] << " at v " << v;
      }
      ASSERT_GE(s.column, last_column_in_row[s.row]);
      last_column_in_row[s.row] = s.column;
      previous = s;
    }
  }
}

// Not asserted: time per sample() and per pdf() query on a 1024 x 512 random-weight map (random inputs:
// the accesses miss the caches as an environment map's do in a render). Independent queries measure
// throughput, chained ones (each waiting for the previous result) latency. Asserted: E[1 / pdf] over the
// samples is the area of the support, 1.
TEST(Distribution2D, MicroBenchmark1024x512) {
  constexpr int kWidth = 1024, kHeight = 512, kQueries = 1 << 19;
  Pcg32 rng(42);
  std::vector<double> w(kWidth * kHeight);
  for (double& x : w) x = 0.01 + rng.next_float();
  const Distribution2D d(w, kWidth, kHeight);
  std::vector<Vec2> u(kQueries);
  std::vector<int> columns(kQueries), rows(kQueries);
  for (int i = 0; i < kQueries; ++i) {
    u[i] = {rng.next_float(), rng.next_float()};
    columns[i] = static_cast<int>(rng.next_uint() % kWidth);
    rows[i] = static_cast<int>(rng.next_uint() % kHeight);
  }
  using Clock = std::chrono::steady_clock;
  const auto ns = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::nano>(b - a).count() / kQueries;
  };
  double best[4] = {1e30, 1e30, 1e30, 1e30}, inverse_pdf = 0.0;
  float last = 0.0f, sink = 0.0f;
  for (int repeat = 0; repeat < 3; ++repeat) {
    inverse_pdf = 0.0;
    const auto t0 = Clock::now();
    for (int i = 0; i < kQueries; ++i) inverse_pdf += 1.0 / d.sample(u[i]).pdf;
    const auto t1 = Clock::now();
    for (int i = 0; i < kQueries; ++i) sink += d.pdf(columns[i], rows[i]);
    const auto t2 = Clock::now();
    // last * 0 is 0 but the compiler must wait for it: each query depends on the previous one.
    for (int i = 0; i < kQueries; ++i) last = d.sample({u[i].x + last * 0.0f, u[i].y}).pdf;
    const auto t3 = Clock::now();
    for (int i = 0; i < kQueries; ++i) last = d.pdf(columns[i] + static_cast<int>(last * 0.0f), rows[i]);
    const auto t4 = Clock::now();
    const double t[4] = {ns(t0, t1), ns(t1, t2), ns(t2, t3), ns(t3, t4)};
    for (int k = 0; k < 4; ++k) best[k] = std::min(best[k], t[k]);
  }
  std::printf(
      "[ bench ] Distribution2D 1024 x 512 (best of 3): sample %.1f ns, pdf %.1f ns; chained: sample %.1f "
      "ns, "
      "pdf %.1f ns (%g)\n",
      best[0], best[1], best[2], best[3], static_cast<double>(sink + last));
  EXPECT_NEAR(inverse_pdf / kQueries, 1.0, 0.01);
}

}  // namespace
}  // namespace ochre::distribution_2d_test
