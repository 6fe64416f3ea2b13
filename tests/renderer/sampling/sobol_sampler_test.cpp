// SobolSampler: (0,2)-net structure, uniformity of the scrambled points, purity (determinism),
// and its error advantage over IndependentSampler on smooth and discontinuous 2D integrands.
#include "renderer/sampling/sobol_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "renderer/sampling/sampler.h"

namespace ochre::sobol_sampler_test {
namespace {

constexpr uint64_t kSeed = 12345;

uint32_t to_bits24(float v) {
  return static_cast<uint32_t>(v * 0x1p24f);  // exact: values are multiples of 2^-24
}

// True when each of the 2^m elementary intervals of every shape 2^-a x 2^-b (a + b = m) holds
// exactly one of the 2^m points.
bool is_02_net(const std::vector<Vec2>& points, int m) {
  if (points.size() != (size_t{1} << m)) return false;
  for (int a = 0; a <= m; ++a) {
    const int b = m - a;
    std::vector<int> count(size_t{1} << m, 0);
    for (const Vec2& p : points) {
      const uint32_t cx = a == 0 ? 0 : to_bits24(p.x) >> (24 - a);
      const uint32_t cy = b == 0 ? 0 : to_bits24(p.y) >> (24 - b);
      ++count[(cx << b) | cy];
    }
    for (int c : count)
      if (c != 1) return false;
  }
  return true;
}

std::vector<Vec2> sobol_points(uint64_t seed, uint64_t pixel, uint32_t dim, uint64_t first, uint64_t n) {
  std::vector<Vec2> points;
  for (uint64_t i = first; i < first + n; ++i) points.push_back(SobolSampler(seed, pixel, i).get_2d(dim));
  return points;
}

TEST(SobolSampler, UnscrambledDimensionsMatchTheSobolSequence) {
  const double expected_dim1[8] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  const double expected_dim0[8] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(sobol_dimension0(i) * 0x1p-32, expected_dim0[i]) << i;
    EXPECT_EQ(sobol_dimension1(i) * 0x1p-32, expected_dim1[i]) << i;
  }
  for (int m : {4, 8, 12}) {
    std::vector<Vec2> points;
    for (uint32_t i = 0; i < (1u << m); ++i)
      points.push_back({static_cast<float>((sobol_dimension0(i) >> 8) * 0x1p-24),
                        static_cast<float>((sobol_dimension1(i) >> 8) * 0x1p-24)});
    EXPECT_TRUE(is_02_net(points, m)) << "m = " << m;
  }
}

// Reference for Sobol dimension 1: the explicit product with the upper triangular Pascal matrix
// mod 2, its entries built by Pascal's rule binomial(j, i) = binomial(j-1, i-1) + binomial(j-1, i).
uint32_t pascal_matrix_reference(uint32_t index) {
  bool binomial_odd[32][32] = {};
  for (int j = 0; j < 32; ++j) {
    binomial_odd[j][0] = true;
    for (int i = 1; i <= j; ++i) binomial_odd[j][i] = binomial_odd[j - 1][i - 1] != binomial_odd[j - 1][i];
  }
  uint32_t result = 0;
  for (int i = 0; i < 32; ++i) {  // output digit i has weight 2^-(i+1)
    bool digit = false;
    for (int j = i; j < 32; ++j) digit ^= binomial_odd[j][i] && ((index >> j) & 1u);
    if (digit) result |= 1u << (31 - i);
  }
  return result;
}

TEST(SobolSampler, SecondDimensionIsThePascalMatrixProduct) {
  for (uint32_t i = 0; i < 4096; ++i) ASSERT_EQ(sobol_dimension1(i), pascal_matrix_reference(i)) << i;
  uint32_t x = 1;
  for (int k = 0; k < 4096; ++k) {
    x = x * 1664525u + 1013904223u;
    ASSERT_EQ(sobol_dimension1(x), pascal_matrix_reference(x)) << x;
  }
}

TEST(SobolSampler, OwenScrambleIsANestedPermutation) {
  // Over all 16-bit prefixes, the scrambled prefixes form a permutation, and the scrambled
  // prefix does not depend on the bits below it.
  for (uint32_t seed : {0u, 1u, 0xdeadbeefu, 0x12345678u}) {
    std::vector<bool> seen(1u << 16, false);
    for (uint32_t prefix = 0; prefix < (1u << 16); ++prefix) {
      const uint32_t top = owen_scramble(prefix << 16, seed) >> 16;
      ASSERT_EQ(owen_scramble((prefix << 16) | (prefix * 2654435761u >> 16), seed) >> 16, top);
      ASSERT_FALSE(seen[top]) << "seed " << seed << " prefix " << prefix;
      seen[top] = true;
    }
  }
}

TEST(SobolSampler, EveryPairIsA02NetForPowerOfTwoSampleCounts) {
  for (int m : {4, 8}) {
    const uint64_t n = uint64_t{1} << m;
    for (uint64_t pixel : {0ull, 1ull, 777ull, 123456789ull}) {
      for (uint32_t dim : {SampleDims::kPixelJitter, SampleDims::bounce(0, SampleDims::kLightPosition),
                           SampleDims::bounce(3, SampleDims::kLobeDirection), 1000u}) {
        EXPECT_TRUE(is_02_net(sobol_points(kSeed, pixel, dim, 0, n), m))
            << "m " << m << " pixel " << pixel << " dim " << dim;
        // A later aligned block of the sample range (one part of a split render) is a net too.
        EXPECT_TRUE(is_02_net(sobol_points(kSeed, pixel, dim, 5 * n, n), m))
            << "block, m " << m << " pixel " << pixel << " dim " << dim;
      }
    }
  }
}

TEST(SobolSampler, OneDimensionIsStratifiedAndMatchesFirstCoordinate) {
  for (uint32_t dim : {0u, 3u, 9u}) {
    std::vector<int> count(256, 0);
    for (uint64_t i = 0; i < 256; ++i) {
      const SobolSampler s(kSeed, 42, i);
      const float v = s.get_1d(dim);
      EXPECT_EQ(v, s.get_2d(dim).x);
      ++count[to_bits24(v) >> 16];
    }
    for (int c : count) EXPECT_EQ(c, 1) << "dim " << dim;
  }
}

double chi_square_uniform(const std::vector<int>& counts, double total) {
  const double expected = total / counts.size();
  double chi2 = 0;
  for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

TEST(SobolSampler, ScrambledPointsAreUniformAcrossPixels) {
  // Sample 0 of an unscrambled sequence is always (0, 0); scrambling must make it uniform over
  // pixels. Also pool a non-power-of-two count (100 samples) where stratification is not exact.
  // 64 bins: chi-square has 63 degrees of freedom, mean 63, sd 11.2; 120 is p ~ 1e-5.
  for (uint64_t samples : {1ull, 100ull}) {
    const int pixels = 20000 / static_cast<int>(samples) + 1000;
    std::vector<int> hist_x(64, 0), hist_y(64, 0);
    double sum_x = 0, sum_y = 0;
    int total = 0;
    for (int p = 0; p < pixels; ++p)
      for (uint64_t i = 0; i < samples; ++i) {
        const Vec2 v = SobolSampler(kSeed, p, i).get_2d(SampleDims::bounce(1, SampleDims::kLobeDirection));
        ASSERT_GE(v.x, 0.0f);
        ASSERT_LT(v.x, 1.0f);
        ASSERT_GE(v.y, 0.0f);
        ASSERT_LT(v.y, 1.0f);
        ++hist_x[static_cast<int>(v.x * 64)];
        ++hist_y[static_cast<int>(v.y * 64)];
        sum_x += v.x;
        sum_y += v.y;
        ++total;
      }
    const double chi_x = chi_square_uniform(hist_x, total), chi_y = chi_square_uniform(hist_y, total);
    std::printf("[ sobol ] %llu spp x %d pixels: mean (%.4f, %.4f), chi2 (%.1f, %.1f) / 63 dof\n",
                static_cast<unsigned long long>(samples), pixels, sum_x / total, sum_y / total, chi_x, chi_y);
    EXPECT_NEAR(sum_x / total, 0.5, 5 * std::sqrt(1.0 / 12 / total));
    EXPECT_NEAR(sum_y / total, 0.5, 5 * std::sqrt(1.0 / 12 / total));
    EXPECT_LT(chi_x, 120);
    EXPECT_LT(chi_y, 120);
  }
}

TEST(SobolSampler, DeterministicPureFunction) {
  // Same inputs, same values, whatever was computed before or in which order.
  std::vector<Vec2> forward, backward;
  for (uint64_t i = 0; i < 64; ++i) forward.push_back(SobolSampler(7, 99, i).get_2d(5));
  for (uint64_t i = 64; i-- > 0;) backward.push_back(SobolSampler(7, 99, i).get_2d(5));
  for (size_t i = 0; i < 64; ++i) {
    EXPECT_EQ(forward[i].x, backward[63 - i].x);
    EXPECT_EQ(forward[i].y, backward[63 - i].y);
  }
  const SobolSampler s(7, 99, 1ull << 40);
  EXPECT_EQ(s.get_1d(3), SobolSampler(7, 99, 1ull << 40).get_1d(3));
}

// Branch j of the k continuations of sample i (integrator.branches) draws index i k + j of the pixel's branch
// stream: the same numbers for any (i, k, j) with the same i k + j, also past 2^32 (the Sobol index's high
// bits select another scramble), and none of the camera samples' numbers.
TEST(SobolSampler, BranchJOfKIsIndexIKPlusJOfTheBranchStream) {
  for (uint32_t dim : {0u, 3u, 11u, 60u}) {
    for (uint64_t i : {uint64_t{5}, (uint64_t{1} << 32) + 3}) {
      const SobolSampler a = SobolSampler(3, 41, i).branch(1, 4), b = SobolSampler(3, 41, 2 * i).branch(1, 2);
      EXPECT_EQ(a.get_2d(dim).x, b.get_2d(dim).x);
      EXPECT_EQ(a.get_2d(dim).y, b.get_2d(dim).y);
      EXPECT_EQ(IndependentSampler(3, 41, i).branch(1, 4).get_1d(dim),
                IndependentSampler(3, 41, 2 * i).branch(1, 2).get_1d(dim));
      EXPECT_NE(a.get_1d(dim), SobolSampler(3, 41, 4 * i + 1).get_1d(dim));  // not the camera stream
      EXPECT_NE(IndependentSampler(3, 41, i).branch(1, 4).get_1d(dim),
                IndependentSampler(3, 41, 4 * i + 1).get_1d(dim));
    }
  }
  // The branches of a pixel's first 16 samples, 4 each, are 64 consecutive points of the stream: a
  // (0,6,2)-net, one point in each of the 8 x 8 cells of every 2D dimension (stratified among themselves and
  // across samples).
  for (uint32_t dim : {7u, 12u}) {
    std::vector<int> cells(64, 0);
    for (uint64_t i = 0; i < 16; ++i)
      for (uint32_t j = 0; j < 4; ++j) {
        const Vec2 p = SobolSampler(9, 123, i).branch(j, 4).get_2d(dim);
        ++cells[static_cast<int>(p.y * 8) * 8 + static_cast<int>(p.x * 8)];
      }
    for (int c : cells) EXPECT_EQ(c, 1) << "dimension " << dim;
  }
}

TEST(SobolSampler, PixelsSeedsDimensionsAndHighIndicesGiveDifferentSequences) {
  auto sequence = [](uint64_t seed, uint64_t pixel, uint32_t dim, uint64_t first) {
    std::vector<float> v;
    for (uint64_t i = first; i < first + 16; ++i) {
      const Vec2 p = SobolSampler(seed, pixel, i).get_2d(dim);
      v.push_back(p.x);
      v.push_back(p.y);
    }
    return v;
  };
  const std::vector<float> base = sequence(1, 10, 3, 0);
  EXPECT_NE(base, sequence(2, 10, 3, 0));                  // seed
  EXPECT_NE(base, sequence(1, 11, 3, 0));                  // pixel
  EXPECT_NE(base, sequence(1, 10, 4, 0));                  // dimension
  EXPECT_NE(base, sequence(1, 10, 3, uint64_t{1} << 32));  // index beyond the 32-bit sequence
  EXPECT_NE(sequence(1, 10, 3, 16), base);                 // next block
}

// RMS error over `pixels` independent replicates of a `samples`-point estimate of integral f.
template <class Sampler>
double rms_error(const std::function<double(double, double)>& f, double exact, int samples, int pixels,
                 uint32_t dim_x, uint32_t dim_y) {
  double sum_sq = 0;
  for (int p = 0; p < pixels; ++p) {
    double sum = 0;
    for (int i = 0; i < samples; ++i) {
      const Sampler s(kSeed, p, i);
      double x, y;
      if (dim_x == dim_y) {
        const Vec2 v = s.get_2d(dim_x);
        x = v.x;
        y = v.y;
      } else {
        x = s.get_1d(dim_x);
        y = s.get_1d(dim_y);
      }
      sum += f(x, y);
    }
    const double err = sum / samples - exact;
    sum_sq += err * err;
  }
  return std::sqrt(sum_sq / pixels);
}

TEST(SobolSampler, LowerErrorThanIndependentSampler) {
  const double gauss_1d = std::sqrt(std::numbers::pi) / 2 * std::erf(1.0);
  const auto smooth = [](double x, double y) { return std::exp(-(x * x + y * y)); };
  const auto disk = [](double x, double y) {
    return (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) < 0.45 * 0.45 ? 1.0 : 0.0;
  };
  struct Case {
    const char* name;
    std::function<double(double, double)> f;
    double exact;
    double min_gain_at_1024;  // required RMS ratio independent / sobol at N = 1024
  } cases[] = {{"exp(-(x^2+y^2))", smooth, gauss_1d * gauss_1d, 4.0},
               {"disk r=0.45", disk, std::numbers::pi * 0.45 * 0.45, 1.0}};
  const uint32_t dim = SampleDims::bounce(0, SampleDims::kLobeDirection);
  for (const Case& c : cases) {
    for (int n : {16, 64, 256, 1024}) {
      const double sobol = rms_error<SobolSampler>(c.f, c.exact, n, 1000, dim, dim);
      const double indep = rms_error<IndependentSampler>(c.f, c.exact, n, 1000, dim, dim);
      std::printf("[ sobol ] %-16s N=%4d  RMS sobol %.3e  independent %.3e  ratio %.1f\n", c.name, n, sobol,
                  indep, indep / sobol);
      if (n >= 64) {
        EXPECT_LT(sobol, indep) << c.name << " N=" << n;
      }
      if (n == 1024) {
        EXPECT_GT(indep / sobol, c.min_gain_at_1024) << c.name;
      }
    }
  }
}

TEST(SobolSampler, PaddedDimensionsAreNotCorrelated) {
  // Two different padded dimensions combined in one integrand. Without the index shuffle both
  // would be scrambles of the same van der Corput point (a scrambled diagonal) and the
  // checkerboard below would have RMS error 0.5 at every N. With it the error must stay near
  // Monte Carlo's 0.5 / sqrt(N). It cannot match it exactly: samples 2k and 2k+1 lie in opposite
  // halves in every dimension (each aligned block stays a net), so they agree on the 2x2
  // checkerboard and its variance is twice Monte Carlo's (RMS x 1.41), the price of keeping
  // every aligned sample block stratified.
  const auto checker = [](double x, double y) { return (x < 0.5) != (y < 0.5) ? 1.0 : 0.0; };
  const auto checker_fine = [](double x, double y) {
    return (static_cast<int>(x * 4) + static_cast<int>(y * 4)) % 2 == 1 ? 1.0 : 0.0;
  };
  const uint32_t a = SampleDims::bounce(0, SampleDims::kLobeChoice);
  const uint32_t b = SampleDims::bounce(0, SampleDims::kRoulette);
  struct Case {
    const char* name;
    std::function<double(double, double)> f;
  } cases[] = {{"2x2", checker}, {"4x4", checker_fine}};
  for (const Case& c : cases) {
    for (int n : {16, 256}) {
      const double sobol = rms_error<SobolSampler>(c.f, 0.5, n, 1000, a, b);
      const double indep = rms_error<IndependentSampler>(c.f, 0.5, n, 1000, a, b);
      const double monte_carlo = 0.5 / std::sqrt(n);
      std::printf(
          "[ sobol ] cross-dimension %s checkerboard N=%4d  RMS sobol %.3e  independent %.3e  MC %.3e\n",
          c.name, n, sobol, indep, monte_carlo);
      EXPECT_LT(sobol, 1.6 * monte_carlo) << c.name << " N=" << n;
    }
  }
}

// With every light sampled at a vertex (integrator.light_selection "all"), the first light's position takes
// the bounce's own pair and each further light a pair no bounce of any depth (max_depth <= 1024) and no other
// light uses.
TEST(SampleDims, EveryLightsPositionHasDimensionsOfItsOwn) {
  constexpr uint32_t kMaxDepth = 1024, kLights = 8;
  const uint32_t past_every_bounce = SampleDims::bounce(kMaxDepth + 1, 0);
  std::vector<uint32_t> pairs;
  for (uint32_t depth = 0; depth <= kMaxDepth; ++depth) {
    EXPECT_EQ(SampleDims::light_position(depth, 0), SampleDims::bounce(depth, SampleDims::kLightPosition));
    for (uint32_t light = 1; light < kLights; ++light) {
      const uint32_t first = SampleDims::light_position(depth, light);
      EXPECT_GE(first, past_every_bounce);
      pairs.push_back(first);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  for (size_t i = 1; i < pairs.size(); ++i) EXPECT_GE(pairs[i] - pairs[i - 1], 2u) << "pairs overlap";
}

}  // namespace
}  // namespace ochre::sobol_sampler_test
