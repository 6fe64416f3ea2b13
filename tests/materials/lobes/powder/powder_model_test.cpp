// The dry-powder BRDF (materials/lobes/powder/powder_model.h) against the checks of docs/materials/powder.md,
// "Validation": finiteness, reciprocity, the enhancement factor, the sign-fixed ladder, the isotropic limit,
// the white furnace, energy of the default material, the scaling and peak of the cyclical term, the
// Harvey-Shack lobe, single scattering at backscatter, the thickness factor.

#include "materials/lobes/powder/powder_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/core/pi.h"
#include "materials/core/vec3d.h"
#include "materials/lobes/powder/pigment_table.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre::test::powder_model_test {
namespace {

Vec3d direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Vec3d random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return direction(std::acos(u(rng)), 2.0 * kPiD * u(rng));
}

// The note's eight stress sets (g = 0.7 and -0.5, rho = 0 and 1, kappa = 0.01 and 50, d = 1 um) and the
// default.
struct Set {
  PowderParams<double> p;
  double rho;
};
std::vector<Set> stress_sets() {
  std::vector<Set> sets;
  auto add = [&](auto change, double rho) {
    PowderParams<double> p;
    change(p);
    sets.push_back({p, rho});
  };
  add([](auto&) {}, 0.752);
  add([](auto& p) { p.g = 0.7; }, 0.6);
  add([](auto& p) { p.g = -0.5; }, 0.6);
  add([](auto&) {}, 0.0);
  add([](auto&) {}, 1.0);
  add([](auto& p) { p.kappa = 0.01; }, 0.8);
  add([](auto& p) { p.kappa = 50.0; }, 0.8);
  add([](auto& p) { p.thickness = 1.0; }, 0.8);
  return sets;
}

TEST(PowderModel, FiniteAndNonNegativeEverywhere) {  // T1
  std::mt19937_64 rng(1);
  for (const Set& s : stress_sets())
    for (double lambda : {0.36, 0.45, 0.55, 0.7, 0.83}) {
      const PowderWavelength<double> w{lambda, s.rho, 0.03};
      for (int i = 0; i < 4000; ++i) {
        const Vec3d wi = random_direction(rng), wo = random_direction(rng);
        const PowderTerms<double> t = powder_terms(s.p, w, wi, wo);
        for (double v : {t.l1, t.l2, t.c, t.s}) {
          ASSERT_TRUE(std::isfinite(v));
          ASSERT_GE(v, 0.0);
        }
      }
    }
}

TEST(PowderModel, FiniteAtExactBackscatterAndGrazing) {  // T2
  for (const Set& s : stress_sets())
    for (double theta : {0.0, 30.0, 80.0, 89.99}) {
      const Vec3d w = direction(theta * kDegD, 0.7);
      const PowderTerms<double> t = powder_terms(s.p, PowderWavelength<double>{0.55, s.rho, 0.03}, w, w);
      for (double v : {t.l1, t.l2, t.c, t.s}) EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << theta;
    }
}

TEST(PowderModel, Reciprocal) {  // T3
  std::mt19937_64 rng(2);
  for (const Set& s : stress_sets()) {
    const PowderWavelength<double> w{0.6, s.rho, 0.03};
    PowderParams<float> pf;
    pf.g = float(s.p.g), pf.kappa = float(s.p.kappa), pf.thickness = float(s.p.thickness);
    const PowderWavelength<float> wf{0.6f, float(s.rho), 0.03f};
    for (int i = 0; i < 2000; ++i) {
      const Vec3d a = random_direction(rng), b = random_direction(rng);
      const double ab = powder_brdf(s.p, w, a, b), ba = powder_brdf(s.p, w, b, a);
      ASSERT_NEAR(ab, ba, 1e-12 * std::max(1.0, std::fabs(ab)));
      const Vec3 af = a.to_float(), bf = b.to_float();
      const float abf = powder_brdf(pf, wf, af, bf), baf = powder_brdf(pf, wf, bf, af);
      ASSERT_NEAR(abf, baf, 1e-6f * std::max(1.0f, std::fabs(abf)));
    }
  }
  // The printed Eq 21 is not reciprocal.
  PowderParams<double> printed;
  printed.ladder = PowderLadder::kPrinted;
  const PowderWavelength<double> w{0.7, 0.752, 0.0318};
  const Vec3d a = direction(20 * kDegD, 0.0), b = direction(60 * kDegD, 2.0);
  EXPECT_GT(std::fabs(powder_terms(printed, w, a, b).l2 - powder_terms(printed, w, b, a).l2), 1e-6);
}

TEST(PowderModel, EnhancementFactorIsTwoAtExactBackscatter) {  // T4
  for (double rho : {0.1, 0.5, 0.752, 0.99, 1.0})
    for (double g : {-0.5, 0.0, 0.7})
      for (double theta : {0.0, 25.0, 60.0, 85.0}) {
        PowderParams<double> p;
        p.g = g;
        const Vec3d w = direction(theta * kDegD, 1.1);
        const PowderTerms<double> t = powder_terms(p, PowderWavelength<double>{0.55, rho, 0.03}, w, w);
        if (t.l2 > 0.0) {
          EXPECT_NEAR((t.l2 + t.c) / t.l2, 2.0, 1e-12) << rho << " " << g << " " << theta;
        }
      }
}

TEST(PowderModel, SymmetricLadderEqualsTheSignFixedEquation21) {  // T5
  std::mt19937_64 rng(3);
  PowderParams<double> p;
  for (double rho : {0.3, 0.752, 0.95}) {
    const double tau = 0.03, c0 = std::sqrt(3.0 * (1.0 - rho) * (1.0 - rho * p.g));
    for (int i = 0; i < 500; ++i) {
      const Vec3d wi = random_direction(rng), wo = random_direction(rng);
      const double mi = wi.z, mo = wo.z;
      // Eq 21 with (1 + mu_o c) in place of the printed (1 - mu_o c), Q of Eq 15e, divided by 4 pi.
      const double q = (1.0 + mi * c0 - (1.0 - mi * c0) * std::exp(-2.0 * c0 * tau)) / (4.0 * c0);
      const double eq21 =
          3.0 * rho * rho / (1.0 - mi * mi * c0 * c0) * (2.0 * q / (1.0 + mo * c0) - mi * mi / (mi + mo));
      EXPECT_NEAR(powder_terms(p, PowderWavelength<double>{0.6, rho, tau}, wi, wo).l2, eq21 / (4.0 * kPiD),
                  1e-10 * std::fabs(eq21));
    }
  }
}

TEST(PowderModel, IsotropicLimitIsEquation14) {  // T6
  std::mt19937_64 rng(4);
  PowderParams<double> p;  // g = 0
  const double rho = 0.7, tau = 0.04, lambda = 0.55;
  for (int i = 0; i < 500; ++i) {
    const Vec3d wi = random_direction(rng), wo = random_direction(rng);
    const double mi = wi.z, mo = wo.z;
    const double f = std::hypot(wo.x - wi.x, wo.y - wi.y), k = 2.0 * kPiD / lambda;
    const double alpha = k / p.kappa * f, u = k / p.kappa * (mi - mo), v = 0.5 * (1.0 / mi + 1.0 / mo);
    const double c = std::sqrt(3.0 * (1.0 - rho) + alpha * alpha);  // Eq 15d
    const double eq14c = 3.0 * rho * rho * (c + v * (1.0 - std::exp(-2.0 * c * tau))) /
                         (2.0 * mi * mo * c * v * ((c + v) * (c + v) + u * u));
    const double eq14a = rho / (4.0 * kPiD) / (mi + mo);
    const PowderTerms<double> t = powder_terms(p, PowderWavelength<double>{lambda, rho, tau}, wi, wo);
    EXPECT_NEAR(t.c, eq14c / (4.0 * kPiD), 1e-12 * eq14c);
    EXPECT_NEAR(t.l1, eq14a, 1e-14);
  }
}

// Directional albedo of the volume terms at incidence wi: (sin^2 theta_o, phi) Gauss-Legendre.
double volume_albedo(const PowderParams<double>& p, const PowderWavelength<double>& w, const Vec3d& wi,
                     bool with_c, int n = 256) {
  const GaussLegendreRule us = gauss_legendre_rule(n, 0.0, 1.0),
                          phis = gauss_legendre_rule(n, 0.0, 2.0 * kPiD);
  double sum = 0.0;
  for (size_t a = 0; a < us.nodes.size(); ++a) {
    const double theta = std::asin(std::sqrt(us.nodes[a]));
    for (size_t b = 0; b < phis.nodes.size(); ++b) {
      const PowderTerms<double> t = powder_terms(p, w, wi, direction(theta, phis.nodes[b]));
      sum += us.weights[a] * phis.weights[b] * 0.5 * (t.l1 + t.l2 + (with_c ? t.c : 0.0));
    }
  }
  return sum;
}

TEST(PowderModel, WhiteFurnaceAlbedo) {  // T7
  PowderParams<double> p;
  const PowderWavelength<double> w{0.7, 1.0, 2.0 / 3.0};
  const double analytic = 0.5 * (1.0 - std::log(2.0)) + 0.75 * (2.0 * std::log(2.0) - 1.0 + 2.0 / 3.0);
  EXPECT_NEAR(volume_albedo(p, w, {0, 0, 1}, false), analytic, 1e-5);
  const double total = volume_albedo(p, w, {0, 0, 1}, true, 512);
  EXPECT_GT(total, 0.943);
  EXPECT_LT(total, 0.9455);
}

TEST(PowderModel, DefaultMaterialConservesEnergy) {  // T8
  const auto table = PigmentTable::named("hematite", PowderTau::kPaper);
  PowderParams<double> p;
  double largest = 0.0;
  for (double lambda_nm = 360.0; lambda_nm <= 830.0; lambda_nm += 10.0) {
    const PowderWavelength<double> w{lambda_nm * 1e-3, table->albedo(float(lambda_nm), 0.05f),
                                     table->tau_o(float(lambda_nm))};
    for (double theta : {0.0, 30.0, 60.0, 80.0, 89.0}) {
      const Vec3d wi = direction(theta * kDegD, 0.0);
      // The surface term's albedo is its total integrated scatter, (4 pi mu_i / lambda)^2 A_s'.
      const double tis = std::pow(4.0 * kPiD * wi.z / w.lambda_um, 2) * p.surface_amplitude;
      const double albedo = volume_albedo(p, w, wi, true, 128) + tis;
      largest = std::max(largest, albedo);
      EXPECT_LE(albedo, 1.0) << lambda_nm << " " << theta;
    }
  }
  std::printf("largest directional albedo of the default hematite powder: %.3f\n", largest);
}

TEST(PowderModel, CyclicalTermScalesWithKappaLambdaAndPeaksAtBackscatter) {  // T9, T10, T11
  PowderParams<double> p;
  PowderParams<double> half = p;
  half.kappa = p.kappa / 2.0;
  std::mt19937_64 rng(5);
  for (int i = 0; i < 200; ++i) {
    const Vec3d wi = random_direction(rng), wo = random_direction(rng);
    const double a = powder_terms(p, PowderWavelength<double>{0.45, 0.7, 0.03}, wi, wo).c;
    const double b = powder_terms(half, PowderWavelength<double>{0.9, 0.7, 0.03}, wi, wo).c;
    EXPECT_NEAR(a, b, 1e-14 * a);
  }
  // Half-width at half maximum of C in the incidence plane (in f = |wo_xy - wi_xy|), for three kappa lambda.
  auto half_width = [](double kappa, double lambda) {
    PowderParams<double> q;
    q.kappa = kappa;
    const PowderWavelength<double> w{lambda, 0.752, 0.0318};
    const Vec3d wi = direction(30 * kDegD, 0.0);
    const double peak = powder_terms(q, w, wi, wi).c;
    double lo = 0.0, hi = 0.5;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      const Vec3d wo = direction(std::asin(std::sin(30 * kDegD) + mid), 0.0);
      (powder_terms(q, w, wi, wo).c > 0.5 * peak ? lo : hi) = mid;
    }
    return lo;
  };
  const double base = half_width(0.25, 0.7);
  EXPECT_NEAR(half_width(0.5, 0.7) / base, 2.0, 0.05);
  EXPECT_NEAR(half_width(0.125, 0.7) / base, 0.5, 0.05);
  // The peak: C along the incidence plane is largest at theta_o = theta_i (backscatter side).
  for (double theta_i : {0.0, 20.0, 50.0}) {
    const Vec3d wi = direction(theta_i * kDegD, 0.0);
    double best = -1.0, best_theta = -100.0;
    for (double t = -80.0; t <= 80.0; t += 0.05) {
      const Vec3d wo = direction(std::fabs(t) * kDegD, t < 0 ? kPiD : 0.0);
      const double c = powder_terms(p, PowderWavelength<double>{0.7, 0.752, 0.0318}, wi, wo).c;
      if (c > best) best = c, best_theta = t;
    }
    EXPECT_NEAR(best_theta, theta_i, 0.051) << theta_i;
  }
}

TEST(PowderModel, HarveyShackLobeAtTheMirrorWithItsTotalIntegratedScatter) {  // T12
  PowderParams<double> p;
  p.correlation_length = 2.0;
  const double sigma = 0.01;  // um rms roughness: A_s' = sigma^2
  // (4 pi sigma mu_i / lambda)^2 is the paraxial result: it holds while the lobe (here sigma_xy = 0.06 in
  // the projected disk) stays clear of the horizon; at 60 degrees the horizon cuts 3.5 % of it.
  for (double theta_i : {0.0, 20.0, 40.0}) {
    const Vec3d wi = direction(theta_i * kDegD, 0.3);
    const PowderWavelength<double> w{0.55, 0.752, 0.0318};
    // Integrate S cos over the hemisphere on a fine grid of the projected disk (d omega cos = dA).
    double sum = 0.0;
    const int n = 1600;
    const double h = 2.0 / n;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const double x = -1.0 + (a + 0.5) * h, y = -1.0 + (b + 0.5) * h;
        if (x * x + y * y >= 1.0) continue;
        sum += powder_terms(p, w, wi, Vec3d(x, y, std::sqrt(1.0 - x * x - y * y))).s * h * h;
      }
    const double tis = std::pow(4.0 * kPiD * sigma * wi.z / w.lambda_um, 2);
    EXPECT_NEAR(sum * sigma * sigma, tis, 0.01 * tis) << theta_i;
    // Its maximum is the mirror direction.
    const Vec3d mirror{-wi.x, -wi.y, wi.z};
    const double at_mirror = powder_terms(p, w, wi, mirror).s;
    EXPECT_GT(at_mirror, powder_terms(p, w, wi, direction((theta_i + 1) * kDegD, 0.3 + kPiD)).s);
  }
}

TEST(PowderModel, SingleScatteringAtBackscatterAndTheThicknessFactor) {  // T13, T16
  for (double g : {-0.5, 0.0, 0.7}) {
    PowderParams<double> p;
    p.g = g;
    const Vec3d w = direction(40 * kDegD, 0.2);
    const double rho = 0.6;
    const double l1 = powder_terms(p, PowderWavelength<double>{0.55, rho, 0.03}, w, w).l1;
    EXPECT_NEAR(l1, rho * (1.0 - g) / (4.0 * kPiD * (1.0 + g) * (1.0 + g)) / (2.0 * w.z), 1e-14);
  }
  PowderParams<double> thin, thick;
  thin.thickness = 1e-4;
  const Vec3d wi = direction(20 * kDegD, 0.0), wo = direction(50 * kDegD, 2.0);
  const PowderWavelength<double> w{0.55, 0.6, 0.03};
  const double infinite = powder_terms(thick, w, wi, wo).l1;
  // Thin layer: [1 - exp(-kappa d (1/mu_i + 1/mu_o))] -> kappa d (1/mu_i + 1/mu_o).
  EXPECT_NEAR(powder_terms(thin, w, wi, wo).l1 / infinite,
              thin.kappa * thin.thickness * (1 / wi.z + 1 / wo.z), 1e-8);
  PowderParams<double> thousand;
  thousand.thickness = 1000.0;  // the paper's samples: 1 mm
  EXPECT_NEAR(powder_terms(thousand, w, wi, wo).l1, infinite, 1e-15);
}

}  // namespace
}  // namespace ochre::test::powder_model_test
