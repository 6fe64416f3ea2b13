// Fresnel amplitudes, reflectances and Mueller matrices against the check values of
// docs/polarization.md (those of Mitsuba 3's test suite) and analytic limits.

#include "materials/lobes/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/core/pi.h"
#include "materials/polarization_test_support.h"

namespace ochre::test::fresnel_test {
namespace {

Mueller make(std::initializer_list<std::initializer_list<float>> rows) {
  Mueller m;
  int r = 0;
  for (const auto& row : rows) {
    int c = 0;
    for (float v : row) m(r, c++) = v;
    ++r;
  }
  return m;
}

TEST(Fresnel, ScalarDielectricValuesOfTheNote) {
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(std::cos(45 * kDegF), 1.5f), 0.0502399f, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(std::cos(10 * kDegF), 1 / 1.5f), 0.0400830f, 1e-6f);
  EXPECT_EQ(fresnel_dielectric(std::cos(45 * kDegF), 1 / 1.5f), 1.0f);  // total internal reflection
  for (float c : {0.0f, 1e-7f, 0.3f, 0.7f, 1.0f}) EXPECT_EQ(fresnel_dielectric(c, 1.0f), 0.0f) << c;
  // The other side: cos < 0 means eta inverted.
  EXPECT_NEAR(fresnel_dielectric(-std::cos(10 * kDegF), 1.5f), 0.0400830f, 1e-6f);
}

TEST(Fresnel, AmplitudeSignsAreVerdet) {
  const auto a = fresnel_amplitudes_dielectric(1.0f, 1.5f);
  EXPECT_NEAR(a.r_s.real(), -0.2f, 1e-6f);
  EXPECT_NEAR(a.r_p.real(), +0.2f, 1e-6f);
  const auto b = fresnel_amplitudes_dielectric(std::cos(45 * kDegF), 1.5f);
  EXPECT_NEAR(b.r_s.real(), -0.3033370f, 1e-6f);
  EXPECT_NEAR(b.r_p.real(), +0.0920134f, 1e-6f);
  EXPECT_NEAR(b.t_s.real(), 1.0f + b.r_s.real(), 1e-6f);  // t_s = 1 + r_s
  EXPECT_NEAR(b.t_p.real(), (1.0f + b.r_p.real()) / 1.5f, 1e-6f);
}

TEST(Fresnel, ScalarAgreesWithAmplitudesAndDoublePrecision) {
  for (float eta : {1.5f, 1 / 1.5f, 2.4f, 1.01f})
    for (float c = 0.0f; c <= 1.0f; c += 1.0f / 64) {
      const auto a = fresnel_amplitudes_dielectric(double(c), double(eta));
      const double f = 0.5 * (std::norm(a.r_s) + std::norm(a.r_p));
      EXPECT_NEAR(fresnel_dielectric(c, eta), f, 2e-6) << eta << " " << c;
      EXPECT_NEAR(specular_reflection(c, eta)(0, 0), f, 2e-6) << eta << " " << c;
    }
}

TEST(Fresnel, BrewsterAngleHasNoPReflection) {
  for (float eta : {1.5f, 1 / 1.5f, 1.33f, 2.0f}) {
    const float cos_b = std::cos(std::atan(eta));
    const auto a = fresnel_amplitudes_dielectric(cos_b, eta);
    EXPECT_NEAR(std::abs(a.r_p), 0.0f, 1e-6f) << eta;
    EXPECT_GT(std::norm(a.r_s), 0.01f);
  }
  // The note's block: 0.0739645 in all four top-left entries, the rest 0, for 1.5 and 1/1.5.
  for (float eta : {1.5f, 1 / 1.5f}) {
    const float v = 0.0739645f;
    expect_mueller(specular_reflection(std::cos(std::atan(eta)), eta),
                   make({{v, v, 0, 0}, {v, v, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}}), 2e-6f);
  }
}

TEST(Fresnel, NormalAndGrazingIncidenceMatrices) {
  expect_mueller(specular_reflection(1.0f, 1.5f),
                 make({{.04f, 0, 0, 0}, {0, .04f, 0, 0}, {0, 0, -.04f, 0}, {0, 0, 0, -.04f}}), 1e-6f);
  expect_mueller(specular_reflection(0.0f, 1.5f), Mueller::identity(), 1e-6f);
  expect_mueller(specular_transmission(1.0f, 1 / 1.5f), absorber(0.96f), 1e-6f);
  // Nearly grazing: finite and close to the identity.
  const Mueller g = specular_reflection(1e-7f, 1.5f);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(g(r, c)));
  expect_mueller(g, Mueller::identity(), 1e-5f);
  expect_mueller(specular_transmission(0.0f, 1.5f), Mueller{}, 0.0f);
}

TEST(Fresnel, TotalInternalReflectionPhase) {
  const float eta = 1 / 1.5f;
  // The phase difference Delta = arg r_p - arg r_s, maximal at cos = 0.6201737, Delta = 0.7895822.
  auto delta = [&](double c) {
    const auto a = fresnel_amplitudes_dielectric(c, double(eta));
    return std::arg(a.r_p) - std::arg(a.r_s);
  };
  double best_c = 0, best = -10;
  const double c_critical = std::sqrt(1.0 - double(eta) * eta);
  for (int i = 1; i < 20000; ++i) {
    const double c = c_critical * i / 20000.0;
    if (delta(c) > best) best = delta(c), best_c = c;
  }
  EXPECT_NEAR(best_c, 0.6201737, 1e-4);
  EXPECT_NEAR(best, 0.7895822, 1e-6);
  // Closed form (Born & Wolf 1.5.58): tan(Delta_max / 2) = (1 - n^2) / (2 n), n = eta.
  EXPECT_NEAR(best, 2 * std::atan((1 - eta * eta) / (2 * eta)), 1e-6);
  const auto a = fresnel_amplitudes_dielectric(0.6201737f, eta);
  EXPECT_TRUE(a.total_internal_reflection);
  EXPECT_NEAR(std::abs(a.r_s), 1.0f, 1e-6f);
  EXPECT_NEAR(std::abs(a.r_p), 1.0f, 1e-6f);
  expect_mueller(
      specular_reflection(0.6201737f, eta),
      make({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0.7041420f, -0.7100592f}, {0, 0, 0.7100592f, 0.7041420f}}),
      2e-6f);
  expect_mueller(specular_transmission(0.6201737f, eta), Mueller{}, 0.0f);
}

TEST(Fresnel, TransmissionAtBrewsterFromInside) {
  const float eta = 1 / 1.5f;
  expect_mueller(specular_transmission(std::cos(std::atan(eta)), eta),
                 make({{0.9260355f, -0.07396451f, 0, 0},
                       {-0.07396451f, 0.9260355f, 0, 0},
                       {0, 0, 0.92307705f, 0},
                       {0, 0, 0, 0.92307705f}}),
                 2e-6f);
}

TEST(Fresnel, DielectricAt45Degrees) {
  expect_mueller(specular_reflection(std::cos(45 * kDegF), 1.5f),
                 make({{0.0502399f, 0.0417735f, 0, 0},
                       {0.0417735f, 0.0502399f, 0, 0},
                       {0, 0, -0.0279111f, 0},
                       {0, 0, 0, -0.0279111f}}),
                 1e-6f);
}

TEST(Fresnel, SilverAt45Degrees) {
  const float n = 0.136125f, k = 4.010625f, c = std::cos(45 * kDegF);
  const auto a = fresnel_amplitudes(c, std::complex<float>(n, -k));
  EXPECT_NEAR(std::norm(a.r_s), 0.9780722f, 2e-6f);
  EXPECT_NEAR(std::norm(a.r_p), 0.9566252f, 2e-6f);
  EXPECT_NEAR(fresnel_conductor(c, n, k), 0.9673487f, 2e-6f);
  const Mueller m = specular_reflection(c, std::complex<float>(n, -k));
  expect_mueller(m,
                 make({{0.9673487f, 0.0107235f, 0, 0},
                       {0.0107235f, 0.9673487f, 0, 0},
                       {0, 0, -0.9107870f, -0.3257540f},
                       {0, 0, 0.3257540f, -0.9107870f}}),
                 2e-6f);
  const Stokes out = m * Stokes{{1, 0, 1, 0}};
  EXPECT_LT(out[2], 0.0f);
  EXPECT_GT(out[3], 0.0f);
}

TEST(Fresnel, ConductorNormalIncidenceReflectance) {
  for (auto [n, k] : {std::pair{0.136125f, 4.010625f}, {0.3239f, 2.5972f}, {4.073f, 0.028f}, {1.2f, 7.0f}}) {
    const float want = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    EXPECT_NEAR(fresnel_conductor(1.0f, n, k), want, 2e-6f) << n << " " << k;
    EXPECT_NEAR(fresnel_conductor(1e-7f, n, k), 1.0f, 1e-5f);  // grazing
    EXPECT_NEAR(fresnel_conductor(0.0f, n, k), 1.0f, 1e-6f);
  }
}

TEST(Fresnel, ConductorWithZeroKIsTheDielectric) {
  for (float eta : {1.5f, 2.4f})
    for (float c : {0.0f, 1e-7f, 0.2f, 0.5f, 0.9f, 1.0f}) {
      EXPECT_NEAR(fresnel_conductor(c, eta, 0.0f), fresnel_dielectric(c, eta), 1e-6f);
      expect_mueller(specular_reflection(c, std::complex<float>(eta, 0.0f)), specular_reflection(c, eta),
                     1e-6f);
    }
}

// n = k = 0 (a constant of 0, or a NaN made 0) would divide by eta^2: the limit eta -> 0 reflects
// everything, and the amplitudes there agree with a tiny index computed by the general formulas.
TEST(Fresnel, VanishingConductorIndexReflectsEverything) {
  for (float c : {0.0f, 1e-7f, 0.3f, 0.7f, 1.0f}) {
    for (float tiny : {0.0f, 1e-20f, 1e-16f}) {
      EXPECT_EQ(fresnel_conductor(c, tiny, 0.0f), 1.0f) << c << " " << tiny;
      EXPECT_EQ(fresnel_conductor(c, 0.0f, tiny), 1.0f) << c << " " << tiny;
    }
    const auto limit = fresnel_amplitudes(double(c), std::complex<double>(0.0));
    const auto near = fresnel_amplitudes(double(c), std::complex<double>(1e-7, 0.0));
    EXPECT_NEAR(std::abs(limit.r_s - near.r_s), 0.0, 1e-6) << c;
    EXPECT_NEAR(std::abs(limit.r_p - near.r_p), 0.0, 1e-6) << c;
    const Mueller m = specular_reflection(c, std::complex<float>(0.0f));
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isfinite(m(r, k)));
    EXPECT_FLOAT_EQ(m(0, 0), 1.0f);
  }
}

TEST(Fresnel, ReflectionPlusTransmissionIsOneOnBothSides) {
  for (float eta : {1.5f, 1.33f, 2.4f})
    for (float side : {1.0f, -1.0f})
      for (int i = 0; i <= 100; ++i) {
        const float c = side * (i / 100.0f);
        const Mueller r = specular_reflection(c, eta), t = specular_transmission(c, eta);
        EXPECT_NEAR(r(0, 0) + t(0, 0), 1.0f, 2e-6f) << eta << " " << c;
        // Separately for s and p light: (M00 + M01) is the s response, (M00 - M01) the p one.
        EXPECT_NEAR(r(0, 0) + r(0, 1) + t(0, 0) + t(0, 1), 1.0f, 2e-6f);
        EXPECT_NEAR(r(0, 0) - r(0, 1) + t(0, 0) - t(0, 1), 1.0f, 2e-6f);
      }
}

TEST(Fresnel, EtaOneIsNoInterface) {
  for (float c : {0.0f, 1e-7f, 0.5f, 1.0f}) {
    expect_mueller(specular_reflection(c, 1.0f), Mueller{}, 0.0f);
    const auto a = fresnel_amplitudes(c, std::complex<float>(1.0f, 0.0f));
    EXPECT_EQ(std::abs(a.r_s), 0.0f);
    if (c > 0.0f) expect_mueller(specular_transmission(c, 1.0f), Mueller::identity(), 1e-6f);
  }
}

TEST(Fresnel, MuellerMatricesArePhysical) {
  // A physical Mueller matrix maps a fully polarized vector to one with degree <= 1 (here == 1,
  // a non-depolarizing element) and M00 >= |M01|.
  for (float c : {0.05f, 0.3f, 0.6201737f, 0.9f})
    for (const Mueller& m : {specular_reflection(c, 1.5f), specular_reflection(c, 1 / 1.5f),
                             specular_reflection(c, std::complex<float>(0.2f, -3.0f))}) {
      EXPECT_GE(m(0, 0) + 1e-7f, std::fabs(m(0, 1)));
      for (const Stokes& in : {Stokes{{1, 0, 0, 1}}, Stokes{{1, 0, 1, 0}}, Stokes{{1, 0.6f, 0, 0.8f}}}) {
        const Stokes out = m * in;
        EXPECT_NEAR(out.degree_of_polarization(), 1.0f, 1e-4f);
      }
    }
}

}  // namespace
}  // namespace ochre::test::fresnel_test
