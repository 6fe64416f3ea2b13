// Planck's law: Stefan-Boltzmann total, Wien's displacement, Rayleigh-Jeans limit, normalization.

#include "spectra/blackbody_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ochre::blackbody_spectrum_test {
namespace {

TEST(Blackbody, IntegratesToStefanBoltzmann) {
  // integral of B_lambda over all wavelengths = sigma T^4 / pi (radiance), with
  // sigma = 5.670374419e-8 W m^-2 K^-4 (CODATA 2018, exact from h, c, k_B).
  for (double T : {1000.0, 2856.0, 6504.0}) {
    // Midpoint rule in log(lambda) from 10 nm to 1 mm.
    const int n = 200000;
    const double a = std::log(10.0), b = std::log(1e6), h = (b - a) / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double lambda_nm = std::exp(a + (i + 0.5) * h);
      sum += planck(lambda_nm, T) * lambda_nm * 1e-9 * h;  // d lambda = lambda d(log lambda), in m
    }
    EXPECT_NEAR(sum / (5.670374419e-8 * std::pow(T, 4) / std::numbers::pi), 1.0, 1e-6) << "T = " << T;
  }
}

TEST(Blackbody, PeakFollowsWiensLaw) {
  // Wien's displacement constant b = 2.897771955e-3 m K (CODATA 2018).
  EXPECT_NEAR(wien_peak_nm(5000.0), 2.897771955e6 / 5000.0, 1e-6);
  const double peak = wien_peak_nm(5000.0);
  EXPECT_GT(planck(peak, 5000.0), planck(peak - 0.01, 5000.0));
  EXPECT_GT(planck(peak, 5000.0), planck(peak + 0.01, 5000.0));
}

TEST(Blackbody, RayleighJeansLimit) {
  // lambda >> hc/kT: B = 2 c k T / lambda^4.
  const double lambda_m = 1.0, T = 300.0;
  const double rj = 2.0 * 299792458.0 * 1.380649e-23 * T / std::pow(lambda_m, 4);
  EXPECT_NEAR(planck(lambda_m * 1e9, T) / rj, 1.0, 1e-4);
  EXPECT_EQ(planck(500.0, 0.0), 0.0);
}

TEST(Blackbody, NormalizedToUnitPeak) {
  const BlackbodySpectrum sun(5778.0f);  // peak ~501.5 nm, inside the visible range
  EXPECT_NEAR(sun.eval(float(wien_peak_nm(5778.0))), 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(sun.max_value(), 1.0f);
  for (int l = 360; l <= 830; l += 5) EXPECT_LE(sun.eval(float(l)), 1.0f);
  EXPECT_NEAR(sun.eval(600.0f), planck(600.0, 5778.0) / planck(wien_peak_nm(5778.0), 5778.0), 1e-6);

  const BlackbodySpectrum lamp(2000.0f);  // peak at 1449 nm: maximum over the range at 830 nm
  EXPECT_FLOAT_EQ(lamp.max_value(), lamp.eval(830.0f));
  EXPECT_LT(lamp.max_value(), 1.0f);
  EXPECT_THROW(BlackbodySpectrum(0.0f), std::invalid_argument);
  EXPECT_THROW(BlackbodySpectrum(-5.0f), std::invalid_argument);
  EXPECT_THROW(BlackbodySpectrum(NAN), std::invalid_argument);
}

}  // namespace
}  // namespace ochre::blackbody_spectrum_test
