// Mie scattering and the derived optics of the powder model: Bohren and Huffman's test case, the Rayleigh
// limit, the extrapolation ratio tau_o, the hematite data and the pigment table's interpolation error.

#include "materials/lobes/powder/powder_optics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "materials/lobes/powder/pigment_table.h"
#include "materials/numerics/mie.h"
#include "spectra/named_spectra.h"

namespace ochre::test::powder_optics_test {
namespace {

TEST(PowderOptics, BohrenHuffmanTestCase) {  // T14
  // BHMIE's example (Bohren and Huffman 1983, Appendix A): m = 1.55, x = 5.213 -> Q_ext = 3.105.
  const MieEfficiencies m = mie_efficiencies({1.55, 0.0}, 5.213);
  EXPECT_NEAR(m.extinction, 3.105, 5e-4);
  EXPECT_NEAR(m.scattering, m.extinction, 1e-12);  // no absorption
  EXPECT_NEAR(m.albedo(), 1.0, 1e-12);
}

TEST(PowderOptics, RayleighLimit) {  // T14
  const std::complex<double> m(3.0, 0.5);
  const std::complex<double> polar = (m * m - 1.0) / (m * m + 2.0);
  for (double x : {1e-3, 1e-2}) {
    const MieEfficiencies e = mie_efficiencies(m, x);
    EXPECT_NEAR(e.scattering / (8.0 / 3.0 * std::pow(x, 4) * std::norm(polar)), 1.0, 20 * x * x);
    EXPECT_NEAR((e.extinction - e.scattering) / (4.0 * x * polar.imag()), 1.0, 20 * x * x);
  }
}

TEST(PowderOptics, ExtrapolationRatio) {  // T15
  EXPECT_NEAR(powder_tau_o(1.0), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(powder_tau_o(1.0, PowderTau::kZhuPineWeitz), 2.0 / 3.0, 1e-12);
  EXPECT_EQ(powder_tau_o(2.9, PowderTau::kTwoThirds), 2.0 / 3.0);
  // Total internal reflection alone: C_i over [0, mu_c] is mu_c^(i+1) / (i+1).
  const double n = 3.0, mu_c = std::sqrt(1.0 - 1.0 / (n * n));
  EXPECT_GT(internal_fresnel_moment(n, 1), mu_c * mu_c / 2.0);
  EXPECT_LT(internal_fresnel_moment(n, 1), 0.5);
  // Hematite's n of about 2.8-3.3 gives tau_o of 0.024-0.04 (the paper's printed Eq 16); the inverse form
  // (Zhu, Pine and Weitz) gives about 14 and more.
  for (double hn : {2.8, 3.0, 3.3}) {
    EXPECT_GT(powder_tau_o(hn), 0.02);
    EXPECT_LT(powder_tau_o(hn), 0.045);
    EXPECT_GT(powder_tau_o(hn, PowderTau::kZhuPineWeitz), 10.0);
  }
}

TEST(PowderOptics, HematiteDefaultsAt700nm) {
  // docs/materials/powder.md: the default grains (b = 50 nm) at 700 nm give rho = 0.752, tau_o = 0.0318.
  const double n = named_spectrum("pigment-hematite-n")->eval(700.0f);
  const double k = named_spectrum("pigment-hematite-k")->eval(700.0f);
  EXPECT_NEAR(n, (2.0 * 2.972 + 2.675) / 3.0, 1e-5);  // (2 o + e) / 3, Querry 1985
  EXPECT_NEAR(k, (2.0 * 0.031 + 0.075) / 3.0, 1e-5);
  EXPECT_NEAR(grain_albedo(n, k, 0.05, 0.7), 0.752, 5e-4);
  EXPECT_NEAR(powder_tau_o(n), 0.0318, 5e-5);
}

TEST(PowderOptics, PigmentTableInterpolation) {
  const auto table = PigmentTable::named("hematite", PowderTau::kPaper);
  const auto n = named_spectrum("pigment-hematite-n"), k = named_spectrum("pigment-hematite-k");
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> errors;
  for (int i = 0; i < 4000; ++i) {
    const double lambda = 360.0 + 470.0 * u(rng), b = 0.002 * std::exp(u(rng) * std::log(2000.0));
    const double exact = grain_albedo(n->eval(float(lambda)), k->eval(float(lambda)), b, lambda * 1e-3);
    errors.push_back(std::fabs(table->albedo(float(lambda), float(b)) - exact));
  }
  std::sort(errors.begin(), errors.end());
  const double median = errors[errors.size() / 2], p99 = errors[errors.size() * 99 / 100],
               worst = errors.back();
  std::printf("pigment table |rho - Mie|: median %.1e, 99th percentile %.1e, max %.1e (%zu KiB)\n", median,
              p99, worst, table->memory_bytes() / 1024);
  EXPECT_LT(median, 2e-4);
  EXPECT_LT(p99, 5e-3);
  EXPECT_LT(worst, 0.02);  // near the sharp Mie resonances of grains of 0.2-0.5 um in the red
  // The default grains are exact at the table's knots and interpolate smoothly between.
  EXPECT_NEAR(table->albedo(700.0f, 0.05f), grain_albedo(n->eval(700.0f), k->eval(700.0f), 0.05, 0.7), 2e-4);
  EXPECT_NEAR(table->tau_o(700.0f), powder_tau_o(n->eval(700.0f)), 1e-6);
}

}  // namespace
}  // namespace ochre::test::powder_optics_test
