// branchless_exp and branchless_log against the library's functions in double precision: within 2 units in
// the last place over the whole range, exact at the points where exactness matters, and clamped (finite)
// outside it.

#include "materials/numerics/branchless_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace ochre::branchless_math_test {
namespace {

// |approximation - exact| in units of the last place of the exact value rounded to float.
double ulps(float approximation, double exact) {
  const float rounded = static_cast<float>(exact);
  const double ulp = std::nextafter(rounded, std::numeric_limits<float>::infinity()) - rounded;
  return std::fabs(approximation - exact) / ulp;
}

TEST(BranchlessMath, ExpWithinTwoUlpsOverItsRange) {
  double worst = 0.0;
  float worst_x = 0.0f;
  auto check = [&](float x) {
    const double e = ulps(branchless_exp(x), std::exp(static_cast<double>(x)));
    if (e > worst) worst = e, worst_x = x;
  };
  constexpr int kSteps = 2'000'000;  // uniform over [-87, 88]
  for (int i = 0; i <= kSteps; ++i) check(-87.0f + 175.0f * static_cast<float>(i) / kSteps);
  for (float x = 1e-30f; x < 1.0f; x *= 1.001f) check(x), check(-x);  // small arguments
  std::printf("branchless_exp: worst %.2f ulp at x = %.9g\n", worst, worst_x);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(branchless_exp(0.0f), 1.0f);
  EXPECT_EQ(branchless_exp(-0.0f), 1.0f);
}

TEST(BranchlessMath, ExpClampsOutsideItsRange) {
  EXPECT_EQ(branchless_exp(-1000.0f), branchless_exp(-87.0f));
  EXPECT_EQ(branchless_exp(1000.0f), branchless_exp(88.0f));
  EXPECT_GT(branchless_exp(-87.0f), 0.0f);
  EXPECT_TRUE(std::isnormal(branchless_exp(-87.0f)));
  EXPECT_TRUE(std::isfinite(branchless_exp(88.0f)));
  EXPECT_TRUE(std::isfinite(branchless_exp(std::numeric_limits<float>::infinity())));
  EXPECT_TRUE(std::isfinite(branchless_exp(std::numeric_limits<float>::quiet_NaN())));
}

TEST(BranchlessMath, LogWithinTwoUlpsOverEveryBinade) {
  double worst = 0.0;
  float worst_x = 0.0f;
  // Every binade from the smallest normal up, densely around 1 where log crosses 0.
  for (float x = std::numeric_limits<float>::min(); x < std::numeric_limits<float>::max() / 1.001f;
       x *= 1.0003f) {
    const double e = ulps(branchless_log(x), std::log(static_cast<double>(x)));
    if (e > worst) worst = e, worst_x = x;
  }
  for (float x = 0.5f; x < 2.0f; x = std::nextafter(x, 3.0f) + 1e-6f) {
    const double e = ulps(branchless_log(x), std::log(static_cast<double>(x)));
    if (e > worst) worst = e, worst_x = x;
  }
  std::printf("branchless_log: worst %.2f ulp at x = %.9g\n", worst, worst_x);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(branchless_log(1.0f), 0.0f);
  EXPECT_EQ(branchless_log(2.0f), static_cast<float>(std::log(2.0)));
}

TEST(BranchlessMath, LogOfZeroAndSubnormalsIsTheSmallestNormalsLog) {
  const float smallest = branchless_log(std::numeric_limits<float>::min());
  EXPECT_NEAR(smallest, std::log(static_cast<double>(std::numeric_limits<float>::min())), 1e-5);
  EXPECT_EQ(branchless_log(0.0f), smallest);
  EXPECT_EQ(branchless_log(std::numeric_limits<float>::denorm_min()), smallest);
  EXPECT_EQ(branchless_log(-1.0f), smallest);
}

}  // namespace
}  // namespace ochre::branchless_math_test
