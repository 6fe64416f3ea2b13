// Film accumulation: exact, order-independent sums (split sample ranges merge bit for bit).
#include "renderer/film/film.h"

#include <gtest/gtest.h>

#include <random>

namespace ochre::film_test {
namespace {

TEST(Film, MeanAndVariance) {
  Film film(1, 1);
  film.add_sample(0, 0, {1, 2, 3});
  film.add_sample(0, 0, {3, 4, 5});
  const XYZ m = film.mean(0, 0);
  EXPECT_FLOAT_EQ(m.x, 2);
  EXPECT_FLOAT_EQ(m.y, 3);
  EXPECT_FLOAT_EQ(m.z, 4);
  EXPECT_DOUBLE_EQ(film.variance_y(0, 0), 2.0);  // samples 2 and 4
  EXPECT_EQ(film.sample_count(0, 0), 2u);
}

// Samples become fixed point (units of 2^-40) rounded to nearest, ties to even, on both conversion paths:
// ordinary values and values too large for a 64-bit integer (1e15 is the clamp).
TEST(Film, FixedPointRoundsToNearestEven) {
  const float unit = 0x1p-40f;
  struct Case {
    float value;
    double expected;
  };
  for (const Case c : {Case{2.5f * unit, 2 * 0x1p-40}, Case{3.5f * unit, 4 * 0x1p-40},
                       Case{-2.5f * unit, -2 * 0x1p-40}, Case{0.75f * unit, 1 * 0x1p-40}, Case{4e6f, 4e6},
                       Case{1e7f, 1e7}, Case{-3e9f, -3e9}, Case{1e20f, 1e15}}) {
    Film film(1, 1);
    film.add_sample(0, 0, {c.value, 0, 0});
    EXPECT_EQ(static_cast<double>(film.mean(0, 0).x), static_cast<double>(static_cast<float>(c.expected)))
        << c.value;
  }
}

TEST(Film, SumIsIndependentOfOrderAndSplit) {
  std::mt19937 rng(7);
  std::lognormal_distribution<float> value(0.0f, 3.0f);  // wide dynamic range, like fireflies
  std::vector<XYZ> samples(1000);
  for (auto& s : samples) s = {value(rng), value(rng), value(rng)};

  Film whole(1, 1), first(1, 1), second(1, 1), reversed(1, 1);
  for (const XYZ& s : samples) whole.add_sample(0, 0, s);
  for (size_t i = 0; i < 377; ++i) first.add_sample(0, 0, samples[i]);
  for (size_t i = 377; i < samples.size(); ++i) second.add_sample(0, 0, samples[i]);
  for (size_t i = samples.size(); i-- > 0;) reversed.add_sample(0, 0, samples[i]);
  second.merge(first);  // merged in the "wrong" order on purpose

  const XYZ a = whole.mean(0, 0), b = second.mean(0, 0), c = reversed.mean(0, 0);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.y, c.y);
  EXPECT_EQ(whole.variance_y(0, 0), second.variance_y(0, 0));
}

}  // namespace
}  // namespace ochre::film_test

namespace ochre::film_test {
namespace {

// The accumulators round-trip exactly (partial-sum files rely on it), also negative and 128-bit values.
TEST(Film, AccumulatorsRoundTripEveryLayer) {
  FilmLayers layers;
  layers.aovs = true;
  layers.stokes = true;
  layers.spectral_bins = 3;
  Film film(2, 1, layers), copy(2, 1, layers);
  const std::vector<std::string> names = film.accumulator_names();
  ASSERT_EQ(names.size(), 5u + 8u + 9u + 3u * 4u);
  EXPECT_EQ(names[4], "count");
  EXPECT_EQ(names[12], "depthHits");
  EXPECT_EQ(names.back(), "S3.bin2");
  for (size_t a = 0; a < names.size(); ++a)
    for (size_t p = 0; p < 2; ++p) {
      const bool count = names[a] == "count" || names[a] == "depthHits";
      const __int128 value =
          count ? static_cast<__int128>(a * 7 + p) : -(static_cast<__int128>(a + 1) << 100) + p;
      film.set_accumulator(a, p, value);
    }
  copy.merge(film);
  for (size_t a = 0; a < names.size(); ++a)
    for (size_t p = 0; p < 2; ++p) EXPECT_TRUE(copy.accumulator(a, p) == film.accumulator(a, p)) << names[a];
}

TEST(Film, MergeAtAnOffsetPlacesATile) {
  Film whole(4, 3), tile(2, 1);
  tile.add_sample(1, 0, {1, 2, 3});
  whole.merge(tile, 2, 2);
  EXPECT_EQ(whole.sample_count(3, 2), 1u);
  EXPECT_EQ(whole.mean(3, 2).y, 2.0f);
  EXPECT_EQ(whole.sample_count(1, 0), 0u);
  EXPECT_THROW(whole.merge(tile, 3, 2), std::invalid_argument);
  FilmLayers aovs;
  aovs.aovs = true;
  EXPECT_THROW(whole.merge(Film(4, 3, aovs)), std::invalid_argument);
}

}  // namespace
}  // namespace ochre::film_test
