// The sigmoid-polynomial spectrum of Jakob & Hanika 2019: sigmoid properties, constants with
// infinite coefficients, exact maximum.

#include "spectra/rgb_sigmoid_polynomial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ochre::rgb_sigmoid_polynomial_test {
namespace {

TEST(RGBSigmoidPolynomial, SigmoidProperties) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(0.0f), 0.5f);
  EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(inf), 1.0f);
  EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(-inf), 0.0f);
  EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(1e30f), 1.0f);
  EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(-1e30f), 0.0f);
  EXPECT_NEAR(RGBSigmoidPolynomial::sigmoid(1.0f), 0.5f + 0.5f / std::sqrt(2.0f), 1e-7f);
  float previous = 0.0f;
  for (float x = -50.0f; x <= 50.0f; x += 0.25f) {
    const float s = RGBSigmoidPolynomial::sigmoid(x);
    EXPECT_NEAR(s + RGBSigmoidPolynomial::sigmoid(-x), 1.0f, 1e-6f);  // point symmetry about (0, 1/2)
    EXPECT_GE(s, previous);
    previous = s;
  }
}

TEST(RGBSigmoidPolynomial, ConstantSpectra) {
  for (float v : {0.0f, 1e-6f, 0.18f, 0.5f, 0.9f, 0.999999f, 1.0f}) {
    const auto p = RGBSigmoidPolynomial::constant(v);
    EXPECT_EQ(p.c0, 0.0f);
    EXPECT_EQ(p.c1, 0.0f);
    for (float l : {360.0f, 555.0f, 830.0f}) EXPECT_NEAR(p.eval(l), v, 1e-6f) << "v = " << v;
  }
  EXPECT_EQ(RGBSigmoidPolynomial::constant(0.0f).eval(500.0f), 0.0f);
  EXPECT_EQ(RGBSigmoidPolynomial::constant(1.0f).eval(500.0f), 1.0f);
  EXPECT_EQ(RGBSigmoidPolynomial::constant(1.0f).max_value(), 1.0f);
  EXPECT_EQ(RGBSigmoidPolynomial::constant(0.0f).max_value(), 0.0f);
}

TEST(RGBSigmoidPolynomial, MaxValueIsTheMaximumOverTheVisibleRange) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int n = 0; n < 200; ++n) {
    // A parabola in normalized wavelength with its vertex anywhere, converted to nm.
    const float a = 40.0f * u(rng), t0 = 0.5f + 0.8f * u(rng), b = 5.0f * u(rng);
    const float w = 470.0f, l0 = 360.0f + t0 * w;
    const RGBSigmoidPolynomial p{a / (w * w), -2.0f * a * l0 / (w * w), a * l0 * l0 / (w * w) + b};
    float brute = 0.0f;
    for (float l = 360.0f; l <= 830.0f; l += 0.05f) brute = std::max(brute, p.eval(l));
    EXPECT_GE(p.max_value(), brute - 1e-5f);
    EXPECT_LE(p.max_value(), brute + 1e-4f);
  }
}

}  // namespace
}  // namespace ochre::rgb_sigmoid_polynomial_test
