// Tabulated (piecewise-linear; clamped or zero outside), constant, scaled and product spectra, and CSV
// loading.

#include "spectra/tabulated_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>

#include "spectra/constant_spectrum.h"
#include "spectra/product_spectrum.h"
#include "spectra/scaled_spectrum.h"
#include "support/spectrum_lanes.h"
#include "support/test_paths.h"

using ochre::test::lanes;

namespace ochre::tabulated_spectrum_test {
namespace {

// Reference evaluation by linear search, clamped outside.
float reference_eval(const std::vector<float>& l, const std::vector<float>& v, float x) {
  if (x <= l.front()) return v.front();
  if (x >= l.back()) return v.back();
  for (std::size_t i = 0; i + 1 < l.size(); ++i)
    if (x >= l[i] && x < l[i + 1]) return v[i] + (x - l[i]) / (l[i + 1] - l[i]) * (v[i + 1] - v[i]);
  return v.back();
}

TEST(TabulatedSpectrum, InterpolatesLinearlyAndClampsOutside) {
  const TabulatedSpectrum s({400.0f, 500.0f, 700.0f}, {0.2f, 0.6f, 0.4f});
  EXPECT_FLOAT_EQ(s.eval(400.0f), 0.2f);
  EXPECT_FLOAT_EQ(s.eval(450.0f), 0.4f);
  EXPECT_FLOAT_EQ(s.eval(500.0f), 0.6f);
  EXPECT_FLOAT_EQ(s.eval(600.0f), 0.5f);
  EXPECT_FLOAT_EQ(s.eval(700.0f), 0.4f);
  // Clamped, not zero: reflectance tables often stop inside the visible range.
  EXPECT_FLOAT_EQ(s.eval(360.0f), 0.2f);
  EXPECT_FLOAT_EQ(s.eval(830.0f), 0.4f);
  EXPECT_FLOAT_EQ(s.max_value(), 0.6f);
  EXPECT_FALSE(s.is_constant());
  const auto sampled = s.sample(SampledWavelengths::fixed(lanes({380.0f, 450.0f, 600.0f, 800.0f})));
  EXPECT_EQ(sampled, lanes({0.2f, s.eval(450.0f), s.eval(600.0f), 0.4f}));
}

// Wavelengths just outside a table's ends: the nearest floats below the first and above the last.
float just_below(float x) {
  return std::nextafter(x, -std::numeric_limits<float>::infinity());
}
float just_above(float x) {
  return std::nextafter(x, std::numeric_limits<float>::infinity());
}

// Both extrapolations on an equally spaced table (the direct-index path) and an irregular one (the search).
const std::vector<std::vector<float>> kTableWavelengths = {{400.0f, 550.0f, 700.0f},
                                                           {400.0f, 500.0f, 700.0f}};
const std::vector<float> kTableValues = {0.2f, 0.6f, 0.4f};

// The values of a spectrum over the 400-700 nm table above at its ends (the table's), just outside, far
// outside and at NaN (the value below the table: finite).
void expect_ends_and_outside(const TabulatedSpectrum& s, float below, float above) {
  EXPECT_EQ(s.eval(400.0f), 0.2f);
  EXPECT_EQ(s.eval(700.0f), 0.4f);
  for (float x : {just_below(400.0f), 399.0f, 360.0f, -1e6f, float(NAN)}) EXPECT_EQ(s.eval(x), below) << x;
  for (float x : {just_above(700.0f), 701.0f, 830.0f, 1e6f}) EXPECT_EQ(s.eval(x), above) << x;
  EXPECT_EQ(s.max_value(), 0.6f);
}

TEST(TabulatedSpectrum, ClampHoldsTheEndValuesOutsideTheTable) {
  for (const auto& l : kTableWavelengths) {
    const TabulatedSpectrum s(l, kTableValues, TableExtrapolation::kClamp);
    expect_ends_and_outside(s, 0.2f, 0.4f);
    EXPECT_EQ(s.sample(SampledWavelengths::fixed(lanes({360.0f, 400.0f, 700.0f, 830.0f}))),
              lanes({0.2f, 0.2f, 0.4f, 0.4f}));
  }
  // The default is clamp, as before the choice existed.
  EXPECT_EQ(TabulatedSpectrum({400.0f, 700.0f}, {0.2f, 0.4f}).eval(800.0f), 0.4f);
}

TEST(TabulatedSpectrum, ZeroVanishesOutsideTheTableOnly) {
  for (const auto& l : kTableWavelengths) {
    const TabulatedSpectrum s(l, kTableValues, TableExtrapolation::kZero);
    expect_ends_and_outside(s, 0.0f, 0.0f);
    // Just inside, the table's interpolation, as with clamp.
    EXPECT_EQ(s.eval(just_above(400.0f)), TabulatedSpectrum(l, kTableValues).eval(just_above(400.0f)));
    EXPECT_EQ(s.eval(just_below(700.0f)), TabulatedSpectrum(l, kTableValues).eval(just_below(700.0f)));
    EXPECT_EQ(s.sample(SampledWavelengths::fixed(lanes({360.0f, 400.0f, 700.0f, 830.0f}))),
              lanes({0.0f, 0.2f, 0.4f, 0.0f}));
  }
}

TEST(TabulatedSpectrum, ExtrapolationDecidesWhetherAFlatTableIsConstant) {
  // Flat over 400-500 nm: constant over [360, 830] only when held beyond the table.
  EXPECT_TRUE(TabulatedSpectrum({400.0f, 500.0f}, {0.3f, 0.3f}, TableExtrapolation::kClamp).is_constant());
  EXPECT_FALSE(TabulatedSpectrum({400.0f, 500.0f}, {0.3f, 0.3f}, TableExtrapolation::kZero).is_constant());
  // A flat table covering the whole range is constant either way; a flat zero table too.
  EXPECT_TRUE(TabulatedSpectrum({300.0f, 900.0f}, {0.3f, 0.3f}, TableExtrapolation::kZero).is_constant());
  EXPECT_TRUE(TabulatedSpectrum({400.0f, 500.0f}, {0.0f, 0.0f}, TableExtrapolation::kZero).is_constant());
  // The peak of a zero-extrapolated table that starts inside the range is found.
  EXPECT_EQ(TabulatedSpectrum({400.0f, 500.0f}, {2.0f, 1.0f}, TableExtrapolation::kZero).max_value(), 2.0f);
}

TEST(TabulatedSpectrum, ExtrapolationNames) {
  EXPECT_EQ(table_extrapolation_from_name("clamp"), TableExtrapolation::kClamp);
  EXPECT_EQ(table_extrapolation_from_name("zero"), TableExtrapolation::kZero);
  EXPECT_EQ(table_extrapolation_from_name("Zero"), std::nullopt);
  EXPECT_EQ(table_extrapolation_from_name(""), std::nullopt);
}

TEST(TabulatedSpectrum, UniformFastPathMatchesSearch) {
  std::vector<float> l, v;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i <= 94; ++i) l.push_back(360.0f + 5.0f * i), v.push_back(uniform(rng));
  const TabulatedSpectrum s(l, v);
  for (int n = 0; n < 20000; ++n) {
    const float x = 350.0f + 490.0f * uniform(rng);
    // The fast path takes the fractional position (lambda - first) / step: float rounding of a position up
    // to 94 steps moves the weight by up to ~1e-5 of one step.
    EXPECT_NEAR(s.eval(x), reference_eval(l, v, x), 2e-5f) << "lambda " << x;
  }
  for (float knot : l) EXPECT_NEAR(s.eval(knot), reference_eval(l, v, knot), 2e-5f);
}

TEST(TabulatedSpectrum, MaxValueCoversOnlyTheVisibleRange) {
  // A peak at 300 nm is outside [360, 830]: the maximum over the range is at its start.
  const TabulatedSpectrum s({300.0f, 400.0f, 900.0f}, {5.0f, 1.0f, 2.0f});
  EXPECT_FLOAT_EQ(s.max_value(), std::max(s.eval(360.0f), s.eval(830.0f)));
  EXPECT_TRUE(TabulatedSpectrum({400.0f, 500.0f}, {0.3f, 0.3f}).is_constant());
}

TEST(TabulatedSpectrum, RejectsInvalidTables) {
  EXPECT_THROW(TabulatedSpectrum({400.0f}, {1.0f}), std::invalid_argument);
  EXPECT_THROW(TabulatedSpectrum({400.0f, 500.0f}, {1.0f}), std::invalid_argument);
  EXPECT_THROW(TabulatedSpectrum({400.0f, 400.0f}, {1.0f, 2.0f}), std::invalid_argument);
  EXPECT_THROW(TabulatedSpectrum({400.0f, 500.0f}, {1.0f, NAN}), std::invalid_argument);
}

// Reported by fuzz_csv (input written by hand): values -3e38 and 3e38 are finite, their difference is not,
// and the interpolation at the knot between them gave 0 * inf = NaN.
TEST(TabulatedSpectrum, RejectsNeighbouringValuesBeyondTheFloatRange) {
  try {
    TabulatedSpectrum({400.0f, 510.0f, 600.0f}, {0.0f, -3e38f, 3e38f});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "TabulatedSpectrum: values at index 1 and 2 differ by more than the float range");
  }
  const TabulatedSpectrum wide({400.0f, 510.0f, 600.0f}, {0.0f, -1.5e38f, 1.5e38f});
  EXPECT_FLOAT_EQ(wide.eval(510.0f), -1.5e38f);
  EXPECT_FLOAT_EQ(wide.eval(555.0f), 0.0f);
}

TEST(TabulatedSpectrum, LoadsCsvColumns) {
  const auto dir = test::scratch_dir();
  const auto path = dir / "nk.csv";
  std::ofstream(path) << "# test table\nwavelength_nm,n,k\n400,1.5,3\n600,1.7,4\n";
  EXPECT_FLOAT_EQ(load_spectrum_csv(path)->eval(500.0f), 1.6f);  // first value column
  EXPECT_FLOAT_EQ(load_spectrum_csv(path, "k")->eval(500.0f), 3.5f);
  EXPECT_FLOAT_EQ(load_spectrum_csv(path, std::size_t{2})->eval(600.0f), 4.0f);
  // Outside the table: clamped by default, or zero on request.
  EXPECT_FLOAT_EQ(load_spectrum_csv(path, "k")->eval(800.0f), 4.0f);
  EXPECT_EQ(load_spectrum_csv(path, "k", TableExtrapolation::kZero)->eval(800.0f), 0.0f);
  EXPECT_EQ(load_spectrum_csv(path, std::size_t{2}, TableExtrapolation::kZero)->eval(800.0f), 0.0f);
  try {
    load_spectrum_csv(path, "eta");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ": no column 'eta'"), std::string::npos) << e.what();
  }
  try {
    load_spectrum_csv(path, std::size_t{0});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  try {
    load_spectrum_csv(dir / "absent.csv");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "absent.csv").string()), std::string::npos) << e.what();
  }
}

TEST(SimpleSpectra, ConstantScaledProduct) {
  const auto c = std::make_shared<ConstantSpectrum>(0.25f);
  EXPECT_FLOAT_EQ(c->eval(123.0f), 0.25f);
  EXPECT_TRUE(c->is_constant());
  EXPECT_EQ(c->sample(SampledWavelengths::sample_visible(0.5f)), SampledSpectrum(0.25f));

  const auto t =
      std::make_shared<TabulatedSpectrum>(std::vector<float>{400.0f, 700.0f}, std::vector<float>{1.0f, 4.0f});
  const ScaledSpectrum scaled(t, 2.0f);
  EXPECT_FLOAT_EQ(scaled.eval(550.0f), 5.0f);
  EXPECT_FLOAT_EQ(scaled.max_value(), 8.0f);
  EXPECT_FALSE(scaled.is_constant());
  EXPECT_TRUE(ScaledSpectrum(c, 3.0f).is_constant());

  const ProductSpectrum product(t, c);
  EXPECT_FLOAT_EQ(product.eval(700.0f), 1.0f);
  EXPECT_FLOAT_EQ(product.max_value(), 1.0f);
  const auto w = SampledWavelengths::fixed(lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  EXPECT_EQ(product.sample(w), t->sample(w) * 0.25f);

  EXPECT_THROW(ScaledSpectrum(nullptr, 1.0f), std::invalid_argument);
  EXPECT_THROW(ProductSpectrum(t, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace ochre::tabulated_spectrum_test
