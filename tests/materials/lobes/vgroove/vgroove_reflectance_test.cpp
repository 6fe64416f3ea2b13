// Reflectance of the V-groove model: energy conservation for ideal mirrors, the flat limit against the
// closed-form hemispherical Fresnel average, the equality of the rigorous and s/p models across the
// grooves, the Brewster dip seen along the grooves, the paper's Tables 1 and 3 within the differences
// docs/materials/vgroove.md explains, and exact integration against sampling of the entry position.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/core/pi.h"
#include "materials/lobes/fresnel.h"
#include "materials/lobes/vgroove/vgroove_reference.h"
#include "materials/numerics/gauss_legendre.h"
#include "spectra/named_spectra.h"

namespace ochre::test::vgroove_reflectance_test {
namespace {

const ChainModel kModels[] = {ChainModel::kRigorous, ChainModel::kUnpolarized, ChainModel::kSeparateSP,
                              ChainModel::kPaperLiteral};
const FacetIndex kSilicon = FacetIndex::conductor(4.073, 0.028);  // 550 nm
const FacetIndex kGlass = FacetIndex::conductor(1.5, 0.0);
const FacetIndex kPaperSilver = FacetIndex::conductor(0.1249, 3.3391);  // the paper's value at 550 nm

double one(const VGroove& g, const Vec3d& e, ChainModel model, const FacetIndex& f, int limit = 0) {
  return directional_reflectance(g, e, model, std::vector<FacetIndex>{f}, limit).reflectance[0];
}

TEST(VGrooveReflectance, IdealMirrorsReflectEverythingAtEveryAngleAndDirection) {
  for (double alpha_deg : {1.0, 2.0, 5.0, 45.0, 90.0, 133.0, 179.9, 180.0}) {
    const VGroove g(alpha_deg * kDegD);
    for (double theta_deg : {0.0, 30.0, 75.0, 89.99})
      for (double phi_deg : {0.0, 45.0, 90.0, 160.0})
        for (ChainModel m : kModels)
          EXPECT_NEAR(
              one(g, groove_direction(theta_deg * kDegD, phi_deg * kDegD), m, FacetIndex::ideal_mirror()),
              1.0, 1e-12)
              << alpha_deg << " " << theta_deg << " " << phi_deg;
  }
}

// (1/pi) int R_F cos dw = 2 int_0^1 R_F(mu) mu dmu, by a fine Gauss-Legendre rule on the Fresnel formula.
double hemispherical_fresnel_average(const FacetIndex& f) {
  const GaussLegendreRule rule = gauss_legendre_rule(400, 0.0, 1.0);
  double sum = 0.0;
  for (size_t i = 0; i < rule.nodes.size(); ++i) {
    const FresnelAmplitudes<double> a = fresnel_amplitudes(rule.nodes[i], f.eta);
    sum += rule.weights[i] * rule.nodes[i] * 0.5 * (std::norm(a.r_s) + std::norm(a.r_p));
  }
  return 2.0 * sum;
}

TEST(VGrooveReflectance, FlatColumnIsTheHemisphericalFresnelAverage) {
  const VGroove flat(std::numbers::pi);
  for (const FacetIndex& f : {kGlass, kSilicon, kPaperSilver, FacetIndex::conductor(0.32, 2.6)}) {
    const double want = hemispherical_fresnel_average(f);
    for (ChainModel m : kModels)
      EXPECT_NEAR(bihemispherical_reflectance(flat, m, std::vector<FacetIndex>{f})[0], want, 2e-6);
  }
  // Black glass n = 1.5: 9.18 %, where the paper prints 8.6 % (what n = 1.46 gives).
  EXPECT_NEAR(hemispherical_fresnel_average(kGlass), 0.0918, 5e-5);
}

TEST(VGrooveReflectance, RigorousEqualsSeparateSPAcrossTheGrooves) {
  // At phi = 0 every plane of incidence is the (y, z) plane: s stays s, p stays p.
  for (double alpha_deg : {30.0, 45.0, 60.0, 90.0, 120.0}) {
    const VGroove g(alpha_deg * kDegD);
    for (double theta_deg : {0.0, 20.0, 50.0, 80.0}) {
      const Vec3d e = groove_direction(theta_deg * kDegD, 0.0);
      EXPECT_NEAR(one(g, e, ChainModel::kRigorous, kSilicon), one(g, e, ChainModel::kSeparateSP, kSilicon),
                  1e-12);
    }
  }
}

TEST(VGrooveReflectance, BrewsterDipAlongTheGroovesOnlyInTheRigorousModel) {
  // Silicon, alpha = 45 deg, phi = 90 deg, 550 nm (the paper's Fig 9b): the rigorous reflectance has a
  // minimum near theta = 61 deg, where light already p-polarized meets a facet near Brewster's angle.
  const VGroove g(45 * kDegD);
  double best = 1.0, best_theta = 0.0;
  for (double theta_deg = 40.0; theta_deg <= 80.0; theta_deg += 0.25) {
    const double r = one(g, groove_direction(theta_deg * kDegD, 90 * kDegD), ChainModel::kRigorous, kSilicon);
    if (r < best) best = r, best_theta = theta_deg;
  }
  EXPECT_NEAR(best_theta, 61.0, 1.5);
  EXPECT_LT(best, 1e-3);
  const Vec3d e = groove_direction(best_theta * kDegD, 90 * kDegD);
  EXPECT_GT(one(g, e, ChainModel::kUnpolarized, kSilicon), 20.0 * best);
  EXPECT_GT(one(g, e, ChainModel::kSeparateSP, kSilicon), 100.0 * best);
}

TEST(VGrooveReflectance, PaperLiteralRotationDiffersFromThreeReflectionsOn) {
  // Eq 33 drops the sign of the rotation between planes of incidence: harmless for one or two
  // reflections (alpha >= 90 deg), about 0.2 points of bi-hemispherical reflectance for silicon at 45 deg.
  const std::vector<FacetIndex> si{kSilicon};
  for (double alpha_deg : {90.0, 120.0})
    EXPECT_NEAR(
        bihemispherical_reflectance(VGroove(alpha_deg * kDegD), ChainModel::kPaperLiteral, si, 0, 32)[0],
        bihemispherical_reflectance(VGroove(alpha_deg * kDegD), ChainModel::kRigorous, si, 0, 32)[0], 1e-12);
  const VGroove g45(45 * kDegD);
  const double diff = bihemispherical_reflectance(g45, ChainModel::kPaperLiteral, si)[0] -
                      bihemispherical_reflectance(g45, ChainModel::kRigorous, si)[0];
  EXPECT_NEAR(diff, -0.0021, 0.0003);
}

TEST(VGrooveReflectance, Table3SilverTotalsAndTruncatedRows) {
  // Totals within 0.3 points of the printed values; the truncated rows come out 1.1-1.7 points above
  // the printed ones in an exact computation (docs/materials/vgroove.md).
  struct Row {
    double alpha;
    int limit;
    double printed;
  };
  const Row rows[] = {{45, 1, 13.4}, {45, 2, 39.0}, {45, 3, 71.3}, {45, 4, 89.7}, {60, 1, 24.3},
                      {60, 2, 66.7}, {60, 3, 92.1}, {90, 1, 54.7}, {90, 2, 94.4}};
  const std::vector<FacetIndex> ag{kPaperSilver};
  for (const Row& r : rows) {
    const VGroove g(r.alpha * kDegD);
    const bool total = r.limit >= g.max_reflections();
    const double ours = 100.0 * bihemispherical_reflectance(g, ChainModel::kRigorous, ag, r.limit)[0];
    if (total)
      EXPECT_NEAR(ours, r.printed, 0.3) << r.alpha << " total";
    else {
      EXPECT_GT(ours - r.printed, 1.1) << r.alpha << " limit " << r.limit;
      EXPECT_LT(ours - r.printed, 1.7) << r.alpha << " limit " << r.limit;
    }
  }
  // At 90 degrees, 58.6 % of the flux is reflected exactly once... times the facet's reflectance, which
  // the 1-reflection row holds; with an ideal mirror it is the fraction itself.
  const double once = bihemispherical_reflectance(VGroove(90 * kDegD), ChainModel::kRigorous,
                                                  std::vector<FacetIndex>{FacetIndex::ideal_mirror()}, 1)[0];
  EXPECT_NEAR(once, 0.586, 0.001);
}

TEST(VGrooveReflectance, Table1WithTheProjectsOpticalData) {
  // 550 nm; the printed table's differences come from the authors' numerical integration and optical
  // data (docs/materials/vgroove.md): within 0.6 points, copper within 1.3, black glass within 0.6.
  auto metal = [](const char* name) {
    const std::string m = name;
    return FacetIndex::conductor(named_spectrum("metal-" + m + "-eta")->eval(550.0f),
                                 named_spectrum("metal-" + m + "-k")->eval(550.0f));
  };
  const std::vector<FacetIndex> facets{kGlass,       metal("Si"), metal("Au"),
                                       kPaperSilver, metal("Cu"), metal("Al")};
  const double printed[6][6] = {{0.9, 1.6, 3.5, 5.5, 7.3, 8.6},       {11.0, 16.6, 26.4, 34.0, 36.8, 37.3},
                                {66.3, 72.9, 80.0, 83.6, 85.1, 85.4}, {89.7, 92.1, 94.4, 95.6, 96.0, 96.1},
                                {33.9, 42.8, 54.4, 61.2, 63.9, 64.6}, {77.1, 82.2, 87.4, 90.2, 91.0, 90.9}};
  const double tolerance[6] = {0.6, 0.6, 0.6, 0.6, 1.3, 0.9};
  const double alphas[6] = {45, 60, 90, 120, 150, 180};
  for (int a = 0; a < 6; ++a) {
    const std::vector<double> r =
        bihemispherical_reflectance(VGroove(alphas[a] * kDegD), ChainModel::kRigorous, facets);
    for (int m = 0; m < 6; ++m)
      EXPECT_NEAR(100.0 * r[m], printed[m][a], tolerance[m]) << "material " << m << " alpha " << alphas[a];
    // Exact integration is monotonic in alpha for every material (the printed Al row is not).
    if (a > 0) {
      const std::vector<double> prev =
          bihemispherical_reflectance(VGroove(alphas[a - 1] * kDegD), ChainModel::kRigorous, facets, 0, 48);
      const std::vector<double> cur =
          bihemispherical_reflectance(VGroove(alphas[a] * kDegD), ChainModel::kRigorous, facets, 0, 48);
      for (int m = 0; m < 6; ++m) EXPECT_GT(cur[m], prev[m]);
    }
  }
}

TEST(VGrooveReflectance, ExactIntegrationEqualsSamplingTheEntryPosition) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<FacetIndex> si{kSilicon};
  for (double alpha_deg : {20.0, 45.0, 100.0}) {
    const VGroove g(alpha_deg * kDegD);
    for (double theta_deg : {15.0, 55.0, 85.0}) {
      const Vec3d e = groove_direction(theta_deg * kDegD, 40 * kDegD);
      const double exact = one(g, e, ChainModel::kRigorous, kSilicon);
      const int n = 20000;
      double sum = 0.0, sum2 = 0.0;
      for (int i = 0; i < n; ++i) {
        const VGroovePath path = g.trace(e, (2.0 * u(rng) - 1.0) * g.half_opening());
        ChainResponse r(ChainModel::kRigorous, kSilicon);
        light_chain(g, path, [&](const ChainStep& s) { r.add(s); });
        sum += r.reflectance();
        sum2 += r.reflectance() * r.reflectance();
      }
      const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
      EXPECT_NEAR(mean, exact, 3.0 * se + 1e-12) << alpha_deg << " " << theta_deg;
    }
  }
}

TEST(VGrooveReflectance, QuadratureConverges) {
  const std::vector<FacetIndex> si{kSilicon};
  const VGroove g(45 * kDegD);
  EXPECT_NEAR(bihemispherical_reflectance(g, ChainModel::kRigorous, si, 0, 96)[0],
              bihemispherical_reflectance(g, ChainModel::kRigorous, si, 0, 192)[0], 2e-6);
}

}  // namespace
}  // namespace ochre::test::vgroove_reflectance_test
