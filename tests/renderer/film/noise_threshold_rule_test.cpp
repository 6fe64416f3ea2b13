// The stopping rule of noise-threshold rendering (renderer/film/noise_threshold.h) on films of known
// samples: the relative standard error sqrt(s^2 / n) / |mean| against the threshold, decisions only at
// 16, 32, 64, ..., and a pixel that stopped takes no further sample.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/film/noise_threshold.h"

namespace ochre::noise_threshold_rule_test {
namespace {

// A 1x1 film holding n samples of Y alternating between a and b.
Film film_of(int n, float a, float b) {
  Film film(1, 1);
  for (int k = 0; k < n; ++k) {
    const float y = k % 2 ? b : a;
    film.add_sample(0, 0, {y, y, y});
  }
  return film;
}

TEST(NoiseThresholdRule, DecisionPointsArePowersOfTwoFromSixteen) {
  for (uint64_t n : {16u, 32u, 64u, 1024u, 1u << 24}) EXPECT_TRUE(is_noise_decision_point(n)) << n;
  for (uint64_t n : {0u, 1u, 2u, 8u, 15u, 17u, 24u, 48u, 1000u})
    EXPECT_FALSE(is_noise_decision_point(n)) << n;
  EXPECT_TRUE(valid_noise_threshold_count(100, 100));
  EXPECT_TRUE(valid_noise_threshold_count(64, 100));
  EXPECT_FALSE(valid_noise_threshold_count(128, 100));
  EXPECT_FALSE(valid_noise_threshold_count(50, 100));
  EXPECT_FALSE(valid_noise_threshold_count(8, 100));
}

TEST(NoiseThresholdRule, RelativeStandardErrorAgainstTheThreshold) {
  // Y = 1.0, 1.2, ...: mean 1.1, sample variance 0.01 * 16 / 15, standard error sqrt(var / 16) = 0.02582,
  // relative 0.02347.
  const Film film = film_of(16, 1.0f, 1.2f);
  const double relative = std::sqrt(0.01 * 16.0 / 15.0 / 16.0) / 1.1;
  EXPECT_NEAR(relative, 0.02347, 1e-5);
  EXPECT_TRUE(pixel_converged(film, 0, 0, relative * 1.001));
  EXPECT_FALSE(pixel_converged(film, 0, 0, relative * 0.999));
  // At a decision point a converged pixel takes no further sample; elsewhere it goes on.
  EXPECT_FALSE(pixel_takes_sample(film, 0, 0, 16, 0.03));
  EXPECT_TRUE(pixel_takes_sample(film, 0, 0, 16, 0.02));
  const Film seventeen = film_of(17, 1.0f, 1.2f);
  EXPECT_TRUE(pixel_takes_sample(seventeen, 0, 0, 17, 0.5));
  // A pixel that holds fewer samples than the next index stopped earlier.
  EXPECT_FALSE(pixel_takes_sample(film, 0, 0, 32, 1e-9));
}

TEST(NoiseThresholdRule, ZeroVarianceHasConvergedAndNegativeMeansUseTheirMagnitude) {
  EXPECT_TRUE(pixel_converged(film_of(16, 0.0f, 0.0f), 0, 0, 1e-6));
  EXPECT_TRUE(pixel_converged(film_of(16, 0.3f, 0.3f), 0, 0, 1e-6));
  const Film negative = film_of(16, -1.0f, -1.2f);  // negative lights (docs/lights.md)
  EXPECT_TRUE(pixel_converged(negative, 0, 0, 0.0235));
  EXPECT_FALSE(pixel_converged(negative, 0, 0, 0.0234));
  EXPECT_FALSE(pixel_converged(film_of(1, 1.0f, 1.0f), 0, 0, 0.5)) << "one sample estimates no variance";
}

}  // namespace
}  // namespace ochre::noise_threshold_rule_test
