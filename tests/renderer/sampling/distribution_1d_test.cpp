// Distribution1D: the guide-table search must return exactly what a full binary search of the CDF
// returns (images must not change with the acceleration), including zero-weight items, u close to 1
// and u on bucket boundaries.

#include "renderer/sampling/distribution_1d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace ochre::distribution_1d_test {
namespace {

// Reference: the item below the first normalised CDF entry above u, skipping zero-weight items.
size_t reference_sample(const std::vector<double>& weights, float u) {
  std::vector<double> cdf(weights.size() + 1, 0.0);
  for (size_t i = 0; i < weights.size(); ++i) cdf[i + 1] = cdf[i] + weights[i];
  const double total = cdf.back();
  for (double& c : cdf) c /= total;
  cdf.back() = 1.0;
  const auto it = std::upper_bound(cdf.begin() + 1, cdf.end(), static_cast<double>(u));
  size_t i = std::min(static_cast<size_t>(it - cdf.begin()) - 1, weights.size() - 1);
  while (weights[i] == 0.0 && i > 0) --i;
  return i;
}

std::vector<float> probe_values(size_t n) {
  std::vector<float> u;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) u.push_back(uniform(rng));
  for (size_t k = 0; k <= n; ++k) {  // bucket boundaries and their float neighbours
    const float b = static_cast<float>(static_cast<double>(k) / n);
    u.push_back(b);
    u.push_back(std::nextafter(b, 0.0f));
    u.push_back(std::nextafter(b, 1.0f));
  }
  u.push_back(0.0f);
  u.push_back(0.99999994f);
  std::erase_if(u, [](float x) { return !(x >= 0.0f && x < 1.0f); });
  return u;
}

void expect_same_as_full_search(const std::vector<double>& weights) {
  const Distribution1D d(weights);
  for (float u : probe_values(weights.size()))
    ASSERT_EQ(d.sample(u), reference_sample(weights, u)) << "u = " << u << ", n = " << weights.size();
}

TEST(Distribution1D, GuideTableMatchesFullSearchOnRandomWeights) {
  std::mt19937 rng(3);
  std::exponential_distribution<double> weight(1.0);
  for (size_t n : {1u, 2u, 3u, 17u, 1000u}) {
    std::vector<double> w(n);
    for (double& x : w) x = weight(rng);
    expect_same_as_full_search(w);
  }
}

TEST(Distribution1D, GuideTableMatchesFullSearchWithZerosAndSpikes) {
  std::vector<double> w(512, 0.0);
  w[0] = 1e-9;
  w[100] = 5.0;
  w[101] = 1e-12;
  w[300] = 1.0;
  w[511] = 0.0;  // trailing zeros: u near 1 must walk back to item 300
  expect_same_as_full_search(w);
  std::vector<double> steep(4096);
  for (size_t i = 0; i < steep.size(); ++i) steep[i] = std::pow(1.01, static_cast<double>(i));
  expect_same_as_full_search(steep);
}

TEST(Distribution1D, RemappedUStaysInsideTheItem) {
  const Distribution1D d({1.0, 3.0});
  float r = -1.0f;
  EXPECT_EQ(d.sample(0.125f, &r), 0u);
  EXPECT_FLOAT_EQ(r, 0.5f);
  EXPECT_EQ(d.sample(0.625f, &r), 1u);
  EXPECT_FLOAT_EQ(r, 0.5f);
}

TEST(Distribution1D, OneItemPassesUThroughUnchanged) {
  // The one-item shortcut must give the bits of the general search: item 0 and u itself.
  const Distribution1D d({2.5});
  for (float u : probe_values(1)) {
    float r = -1.0f;
    ASSERT_EQ(d.sample(u, &r), 0u);
    ASSERT_EQ(r, u);
  }
}

TEST(Distribution1D, AllZeroWeightsStillReturnAValidIndex) {
  const Distribution1D d({0.0, 0.0, 0.0});
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(d.sample(0.7f), 0u);
}

}  // namespace
}  // namespace ochre::distribution_1d_test
