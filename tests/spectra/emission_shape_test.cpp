// Emission shapes (spectra/emission_shape.h): what `ochre relight` divides out per spectral bin.
#include "spectra/emission_shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "spectra/blackbody_spectrum.h"
#include "spectra/cie.h"
#include "spectra/constant_spectrum.h"
#include "spectra/scaled_spectrum.h"

namespace ochre::emission_shape_test {
namespace {

TEST(EmissionShape, IsTheSpectrumOverItsLuminance) {
  const BlackbodySpectrum warm(1850.0f);
  const std::vector<double> shape = *emission_shape(warm);
  ASSERT_EQ(shape.size(), 471u);
  const double luminance = spectrum_to_xyz(warm).y;
  EXPECT_NEAR(shape[200], warm.eval(560.0f) / luminance, 1e-6 * shape[200]);
  // The intensity divides out: a scaled spectrum has the same shape.
  const ScaledSpectrum brighter(std::make_shared<BlackbodySpectrum>(1850.0f), 7.5f);
  EXPECT_TRUE(same_emission_shape(shape, *emission_shape(brighter)));
  EXPECT_FALSE(same_emission_shape(shape, *emission_shape(BlackbodySpectrum(1900.0f))));
  EXPECT_FALSE(emission_shape(ConstantSpectrum(0.0f)).has_value()) << "no luminance, no shape";
}

TEST(EmissionShape, TextRoundTripsAndBadTextIsRefused) {
  const std::vector<double> shape = *emission_shape(BlackbodySpectrum(2700.0f));
  const std::optional<std::vector<double>> back = parse_emission_shape(format_emission_shape(shape));
  ASSERT_TRUE(back.has_value());
  for (size_t i = 0; i < shape.size(); ++i) EXPECT_NEAR((*back)[i], shape[i], 1e-8 * shape[i]);
  EXPECT_FALSE(parse_emission_shape("1 2 3").has_value()) << "471 values";
  std::string negative = format_emission_shape(shape);
  negative.replace(0, negative.find(' '), "-1");
  EXPECT_FALSE(parse_emission_shape(negative).has_value());
  EXPECT_FALSE(parse_emission_shape(format_emission_shape(shape) + " 1").has_value());
  EXPECT_FALSE(parse_emission_shape("").has_value());
}

TEST(EmissionShape, BinRatiosAreTheRatiosOfTheBinIntegrals) {
  const std::vector<double> from = *emission_shape(BlackbodySpectrum(1700.0f));
  const std::vector<double> to = *emission_shape(BlackbodySpectrum(2600.0f));
  // The same shape: every ratio 1.
  for (const double r : emission_bin_ratios(from, from, 16, 360, 830)) EXPECT_NEAR(r, 1.0, 1e-12);
  // Bins of exactly 1 nm from 400 nm: the mean of the linear pieces over [400 + b, 401 + b].
  const std::vector<double> ratios = emission_bin_ratios(from, to, 10, 400, 410);
  for (int b = 1; b < 9; ++b) {
    const size_t i = static_cast<size_t>(40 + b);
    EXPECT_NEAR(ratios[static_cast<size_t>(b)], (to[i] + to[i + 1]) / (from[i] + from[i + 1]), 1e-12) << b;
  }
  // The first and last bins reach to 360 and 830 nm; a hotter blackbody has relatively more blue.
  EXPECT_GT(ratios.front(), ratios.back());
  // One bin: the ratio of the integrals over 360..830 nm (the luminances are equal, not the integrals).
  const std::vector<double> one = emission_bin_ratios(from, to, 1, 360, 830);
  double a = 0, b = 0;
  for (size_t i = 0; i + 1 < from.size(); ++i) {
    a += 0.5 * (from[i] + from[i + 1]);
    b += 0.5 * (to[i] + to[i + 1]);
  }
  EXPECT_NEAR(one[0], b / a, 1e-12 * b / a);
}

TEST(EmissionShape, BinRatiosPerXyzWeighTheColourMatchingFunctions) {
  const std::vector<double> from = *emission_shape(BlackbodySpectrum(1700.0f));
  const std::vector<double> to = *emission_shape(BlackbodySpectrum(2600.0f));
  for (const auto& bin : emission_bin_ratios_xyz(from, from, 4, 360, 830))
    for (const double r : bin) EXPECT_NEAR(r, 1.0, 1e-12);
  // Narrow bins: the colour-matching functions hardly vary across one, so every component is the plain ratio.
  const std::vector<double> plain = emission_bin_ratios(from, to, 470, 360, 830);
  const std::vector<std::array<double, 3>> xyz = emission_bin_ratios_xyz(from, to, 470, 360, 830);
  for (size_t b = 50; b < 300; b += 50)
    for (const double r : xyz[b]) EXPECT_NEAR(r, plain[b], 2e-3 * plain[b]) << b;
  // A wide bin (360..477.5 nm): zbar peaks at its long end, where the hotter blackbody gains least, so Z's
  // ratio lies below the bin's plain ratio; and each is the ratio of the weighted integrals.
  const std::vector<std::array<double, 3>> wide = emission_bin_ratios_xyz(from, to, 4, 360, 830);
  EXPECT_LT(wide[0][2], emission_bin_ratios(from, to, 4, 360, 830)[0]);
  double a = 0, c = 0;
  for (int nm = 360; nm < 477; ++nm) {
    const size_t i = static_cast<size_t>(nm - 360);
    const double w0 = cie_z(float(nm)), w1 = cie_z(float(nm + 1));
    a += 0.5 * (from[i] * w0 + from[i + 1] * w1);
    c += 0.5 * (to[i] * w0 + to[i + 1] * w1);
  }
  // The last half nanometre, to the bin's edge at 477.5 nm (trapezoids of the linear pieces, as the code).
  const double z0 = cie_z(477.0f), z1 = cie_z(477.5f);
  a += 0.25 * (from[117] * z0 + 0.5 * (from[117] + from[118]) * z1);
  c += 0.25 * (to[117] * z0 + 0.5 * (to[117] + to[118]) * z1);
  EXPECT_NEAR(wide[0][2], c / a, 1e-9 * c / a);
}

}  // namespace
}  // namespace ochre::emission_shape_test
