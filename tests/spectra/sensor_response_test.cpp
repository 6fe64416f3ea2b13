// Camera sensor responses (spectra/sensor_response.h) and the white-balance fit (spectra/white_balance.h).
#include "spectra/sensor_response.h"

#include <gtest/gtest.h>

#include <memory>

#include "spectra/blackbody_spectrum.h"
#include "spectra/cie.h"
#include "spectra/constant_spectrum.h"
#include "spectra/embedded_tables.h"
#include "spectra/named_spectra.h"
#include "spectra/product_spectrum.h"
#include "spectra/rgb_spectrum.h"
#include "spectra/tabulated_spectrum.h"
#include "spectra/white_balance.h"

namespace ochre::sensor_response_test {
namespace {

SensorResponse table_sensor(std::string_view file, float lo, float hi) {
  const CsvTable& t = embedded_table(file);
  return SensorResponse(std::string(file), *tabulated_spectrum(t, "r", TableExtrapolation::kZero),
                        *tabulated_spectrum(t, "g", TableExtrapolation::kZero),
                        *tabulated_spectrum(t, "b", TableExtrapolation::kZero), lo, hi);
}

// A "camera" whose sensitivities are the CIE colour matching functions.
SensorResponse cmf_sensor() {
  return SensorResponse("cmf", *named_spectrum("cie_x"), *named_spectrum("cie_y"), *named_spectrum("cie_z"),
                        360.0f, 830.0f);
}

TEST(SensorResponse, ObserverIsTheCieIntegralBitForBit) {
  const SensorPtr observer = cie1931_sensor();
  EXPECT_TRUE(observer->is_cie_observer());
  for (float u : {0.0f, 0.1234f, 0.5f, 0.99999f}) {
    const SampledWavelengths a = observer->sample_wavelengths(u), b = SampledWavelengths::sample_visible(u);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      EXPECT_EQ(a[i], b[i]);
      EXPECT_EQ(a.pdf()[i], b.pdf()[i]);
    }
    const SampledSpectrum L(0.7f);
    const XYZ x = observer->response(L, a), y = sampled_to_xyz(L, b);
    EXPECT_EQ(x.x, y.x);
    EXPECT_EQ(x.y, y.y);
    EXPECT_EQ(x.z, y.z);
  }
}

TEST(SensorResponse, ConstantRadianceGivesGreenOne) {
  const SensorResponse canon = table_sensor("camera_canon_5d_mark_ii_10nm.csv", 400, 720);
  EXPECT_NEAR(canon.response_of(ConstantSpectrum(1.0f)).y, 1.0f, 1e-5f);
  EXPECT_EQ(canon.sensitivity(0, 399.0f), 0.0f);
  EXPECT_EQ(canon.sensitivity(1, 721.0f), 0.0f);
  EXPECT_GT(canon.sensitivity(1, 510.0f), 0.0f);
}

// The Monte-Carlo estimate from sampled wavelengths converges to the 1 nm integral: the sampling pdf and
// the estimator agree, also beyond 830 nm for the infrared sensor.
TEST(SensorResponse, SampledEstimateIsUnbiased) {
  const SpectrumPtr light = std::make_shared<BlackbodySpectrum>(1700.0f);
  for (const SensorResponse& sensor : {table_sensor("camera_nokia_n900_10nm.csv", 400, 720),
                                       table_sensor("sensor_ir720_model_10nm.csv", 360, 1000)}) {
    const XYZ exact = sensor.response_of(*light);
    double sum[3] = {0, 0, 0};
    const int n = 200000;
    bool beyond_830 = false;
    for (int k = 0; k < n; ++k) {
      const SampledWavelengths lambda = sensor.sample_wavelengths((k + 0.5f) / n);
      for (int i = 0; i < kSpectrumSamples; ++i) {
        EXPECT_GE(lambda[i], sensor.lambda_min());
        EXPECT_LE(lambda[i], sensor.lambda_max());
        // The pdf of the 1 nm bin the wavelength fell in (a wavelength on a bin edge may round into either).
        const float pdf = lambda.pdf()[i], l = lambda[i];
        EXPECT_TRUE(pdf == sensor.wavelength_pdf(l) || pdf == sensor.wavelength_pdf(l - 1e-3f) ||
                    pdf == sensor.wavelength_pdf(l + 1e-3f))
            << l;
        beyond_830 = beyond_830 || lambda[i] > 830.0f;
      }
      const XYZ c = sensor.response(light->sample(lambda), lambda);
      sum[0] += c.x;
      sum[1] += c.y;
      sum[2] += c.z;
    }
    EXPECT_NEAR(sum[0] / n / exact.x, 1.0, 2e-3) << sensor.name();
    EXPECT_NEAR(sum[1] / n / exact.y, 1.0, 2e-3) << sensor.name();
    EXPECT_NEAR(sum[2] / n / exact.z, 1.0, 2e-3) << sensor.name();
    EXPECT_EQ(beyond_830, sensor.lambda_max() > 830.0f) << sensor.name();
  }
}

TEST(SensorResponse, BadRangesAreRefused) {
  const ConstantSpectrum one(1.0f), zero(0.0f);
  EXPECT_THROW(SensorResponse("x", one, one, one, 500, 500), std::invalid_argument);
  EXPECT_THROW(SensorResponse("x", one, zero, one, 400, 700), std::invalid_argument);  // no green
}

TEST(WhiteBalance, MapsTheIlluminantsWhiteOntoD65White) {
  const SensorResponse canon = table_sensor("camera_canon_5d_mark_ii_10nm.csv", 400, 720);
  for (const SpectrumPtr& light :
       {d65(), normalized_to_unit_luminance(std::make_shared<BlackbodySpectrum>(1700.0f))}) {
    const Mat3 M = white_balance_matrix(canon, light);
    const XYZ c = canon.response_of(*light);
    const Array3d xyz = M * Array3d{c.x, c.y, c.z};
    const XYZ w = spectrum_to_xyz(*d65());
    EXPECT_NEAR(xyz[0], w.x, 1e-5);
    EXPECT_NEAR(xyz[1], w.y, 1e-5);
    EXPECT_NEAR(xyz[2], w.z, 1e-5);
  }
}

// A camera that sees like the observer needs no correction under D65: the fit is the identity.
TEST(WhiteBalance, ObserverLikeCameraGivesTheIdentity) {
  const Mat3 M = white_balance_matrix(cmf_sensor(), d65());
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(M(r, c), r == c ? 1.0 : 0.0, 2e-3) << r << c;
}

TEST(WhiteBalance, CheckerHasItsPatches) {
  ASSERT_EQ(colorchecker_patches().size(), 24u);
  EXPECT_EQ(colorchecker_patch_names().front(), "dark_skin");
  EXPECT_EQ(colorchecker_patch_names().back(), "black_2");
  EXPECT_FLOAT_EQ(colorchecker_patches()[18]->eval(550.0f), 0.914f);  // white 9.5 at 550 nm (BabelColor)
}

// Spectra beyond the visible for infrared sensors: tables reach past 830 nm where they have data and hold
// their end values beyond; RGB-upsampled spectra hold their 360 / 830 nm values.
TEST(SpectraBeyondTheVisible, DocumentedExtrapolation) {
  const SpectrumPtr n = named_spectrum("pigment-hematite-n");
  EXPECT_FLOAT_EQ(n->eval(870.0f), 2.728f);     // Querry's data reach 900 nm
  EXPECT_EQ(n->eval(950.0f), n->eval(900.0f));  // held beyond
  const RGBAlbedoSpectrum red(RGB{0.6f, 0.1f, 0.05f});
  EXPECT_EQ(red.eval(1000.0f), red.eval(830.0f));
  EXPECT_EQ(red.eval(300.0f), red.eval(360.0f));
  EXPECT_GT(BlackbodySpectrum(1700.0f).eval(1000.0f), BlackbodySpectrum(1700.0f).eval(830.0f));
}

}  // namespace
}  // namespace ochre::sensor_response_test
