// The half-space simulation against exact results: the closed-form single scattering (d'Eon Eq 17),
// Chandrasekhar's H-function BRDF for isotropic scattering, reciprocity, and energy conservation.

#include "tools/halfspace/halfspace_mc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "chandrasekhar_h.h"
#include "materials/core/pi.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre::halfspace::test::halfspace_mc_test {
namespace {

constexpr double kSigmas = 4.0;

Direction at(double mu, double phi_deg) {
  return direction_from_angles(mu, phi_deg * kPiD / 180.0);
}

double combined_se(const Estimate& a, const Estimate& b) {
  return std::hypot(a.standard_error, b.standard_error);
}

TEST(HalfspaceMc, SingleScatteringMatchesClosedForm) {
  // f1 = c p(-wi.wo) / (mu_i + mu_o), d'Eon Eq 17, at several (c, mu_i) with a grid of wo.
  struct Case {
    double c, mu_i;
  };
  const Case cases[] = {{0.3, 0.9}, {0.8, 0.15}, {0.99, 0.5}, {1.0, 0.7}};
  std::vector<Direction> outgoing;
  for (double mu_o : {0.05, 0.3, 0.7, 1.0})
    for (double phi : {0.0, 60.0, 135.0, 180.0}) outgoing.push_back(at(mu_o, phi));
  SimulationOptions options;
  options.max_collisions = 1;  // single scattering is complete after the first collision
  uint64_t seed = 100;
  for (const Case& k : cases) {
    const Direction wi = at(k.mu_i, 0.0);
    const GridResult r = simulate_brdf_grid(k.c, wi, outgoing, 200'000, seed++, options);
    for (size_t i = 0; i < outgoing.size(); ++i) {
      const Direction& wo = outgoing[i];
      const double expected = k.c * lambertian_sphere_phase(-dot(wi, wo)) / (wi.z + wo.z);
      const Estimate& single = r.brdf[i].single;
      EXPECT_NEAR(single.mean, expected, kSigmas * single.standard_error)
          << "c " << k.c << " mu_i " << k.mu_i << " mu_o " << wo.z << " direction " << i;
      EXPECT_LT(single.standard_error, 0.01 * expected) << "the test has power";
    }
  }
}

TEST(HalfspaceMc, NoAbsorptionOrScatteringAtZeroAlbedo) {
  const Direction wi = at(0.6, 0.0), wo = at(0.4, 30.0);
  const GridResult r = simulate_brdf_grid(0.0, wi, {wo}, 10'000, 3);
  EXPECT_EQ(r.brdf[0].multiple.mean, 0.0);
  EXPECT_EQ(r.brdf[0].single.mean, 0.0);
  EXPECT_EQ(r.albedo.mean, 0.0);
  EXPECT_EQ(r.collisions, r.paths) << "every walk ends at its first collision";
}

TEST(HalfspaceMc, TotalIsReciprocal) {
  struct Pair {
    double c, mu_a, mu_b, phi;
  };
  const Pair pairs[] = {{0.8, 0.2, 0.9, 60.0}, {0.99, 0.1, 0.6, 150.0}, {0.8, 0.5, 1.0, 0.0}};
  uint64_t seed = 200;
  for (const Pair& p : pairs) {
    const HalfspaceResult ab = simulate_brdf(p.c, at(p.mu_a, 0.0), at(p.mu_b, p.phi), 100'000, seed++);
    const HalfspaceResult ba = simulate_brdf(p.c, at(p.mu_b, 0.0), at(p.mu_a, p.phi), 100'000, seed++);
    EXPECT_NEAR(ab.total.mean, ba.total.mean, kSigmas * combined_se(ab.total, ba.total))
        << "c " << p.c << " mu " << p.mu_a << ", " << p.mu_b << " phi " << p.phi;
    EXPECT_NEAR(ab.multiple.mean, ba.multiple.mean, kSigmas * combined_se(ab.multiple, ba.multiple));
    EXPECT_LT(ab.total.standard_error, 0.02 * ab.total.mean) << "the test has power";
  }
}

// Directional albedo from the next-event estimates, int f mu_o d(omega) over the upper hemisphere:
// Gauss-Legendre in mu_o, midpoint rule in phi over [0, pi] doubled (the BRDF is even in phi).
struct HemisphereQuadrature {
  std::vector<Direction> directions;
  std::vector<double> weights;
  HemisphereQuadrature(int mu_nodes, int phi_nodes) {
    const GaussLegendreRule rule = gauss_legendre_rule(mu_nodes, 0.0, 1.0);
    const std::vector<double>&x = rule.nodes, &w = rule.weights;
    for (int i = 0; i < mu_nodes; ++i)
      for (int j = 0; j < phi_nodes; ++j) {
        directions.push_back(direction_from_angles(x[i], kPiD * (j + 0.5) / phi_nodes));
        weights.push_back(w[i] * x[i] * 2.0 * kPiD / phi_nodes);
      }
  }
  Estimate integrate(const GridResult& r) const {
    Estimate sum;
    double variance_bound = 0.0;  // errors added linearly: the estimates share their walks
    for (size_t i = 0; i < weights.size(); ++i) {
      sum.mean += weights[i] * r.brdf[i].total.mean;
      variance_bound += weights[i] * r.brdf[i].total.standard_error;
    }
    sum.standard_error = variance_bound;
    return sum;
  }
};

TEST(HalfspaceMc, NextEventAlbedoEqualsCountedEscapes) {
  // Two independent routes to the directional albedo: the counted escaping weight, and the integral of
  // the next-event BRDF estimates over the hemisphere. Their agreement checks the estimator's
  // normalisation (the 1/mu_o and the attenuation), not just its shape.
  const HemisphereQuadrature quadrature(20, 12);
  struct Case {
    double c, mu_i;
    uint64_t paths;
  };
  const Case cases[] = {{0.8, 0.3, 20'000}, {0.8, 1.0, 20'000}, {1.0, 0.6, 3'000}};
  SimulationOptions options;
  options.max_collisions = 100'000;
  uint64_t seed = 300;
  for (const Case& k : cases) {
    const GridResult r =
        simulate_brdf_grid(k.c, at(k.mu_i, 0.0), quadrature.directions, k.paths, seed++, options);
    const Estimate integrated = quadrature.integrate(r);
    SCOPED_TRACE(testing::Message() << "c " << k.c << " mu_i " << k.mu_i << ": counted " << r.albedo.mean
                                    << " +- " << r.albedo.standard_error << ", integrated " << integrated.mean
                                    << " +- " << integrated.standard_error);
    EXPECT_NEAR(integrated.mean, r.albedo.mean,
                kSigmas * std::hypot(integrated.standard_error, r.albedo.standard_error) + 2e-3);
  }
}

TEST(HalfspaceMc, ConservativeHalfspaceReflectsEverything) {
  // c = 1: every walk escapes eventually; the weight still in flight at the cut decays like
  // 1 / sqrt(pi n) with the cut n (first-passage time of a one-dimensional random walk).
  for (uint64_t cut : {1'000u, 100'000u}) {
    SimulationOptions options;
    options.max_collisions = cut;
    const GridResult r = simulate_brdf_grid(1.0, at(0.5, 0.0), {at(0.5, 0.0)}, 4'000, 17, options);
    EXPECT_NEAR(r.albedo.mean + r.truncated_weight, 1.0, 1e-12) << "no weight is lost at c = 1";
    EXPECT_LT(r.truncated_weight, 3.0 / std::sqrt(kPiD * cut)) << "cut " << cut;
  }
}

TEST(HalfspaceMc, IsotropicScatteringMatchesChandrasekhar) {
  // f = c H(mu_i) H(mu_o) / (4 pi (mu_i + mu_o)) (d'Eon Eq 21) for isotropic scattering.
  SimulationOptions options;
  options.phase = PhaseFunction::kIsotropic;
  struct Case {
    double c;
    uint64_t paths;
  };
  uint64_t seed = 400;
  for (const Case& k : {Case{0.9, 40'000}, Case{1.0, 4'000}}) {
    const ChandrasekharH h(k.c);
    for (double mu_i : {0.2, 0.9}) {
      std::vector<Direction> outgoing = {at(0.1, 0.0), at(0.5, 90.0), at(1.0, 0.0)};
      const GridResult r = simulate_brdf_grid(k.c, at(mu_i, 0.0), outgoing, k.paths, seed++, options);
      for (size_t i = 0; i < outgoing.size(); ++i) {
        const double mu_o = outgoing[i].z;
        const double expected = k.c * h(mu_i) * h(mu_o) / (4.0 * kPiD * (mu_i + mu_o));
        EXPECT_NEAR(r.brdf[i].total.mean, expected, kSigmas * r.brdf[i].total.standard_error)
            << "c " << k.c << " mu_i " << mu_i << " mu_o " << mu_o;
      }
    }
  }
}

TEST(HalfspaceMc, ChandrasekharHMatchesKnownValues) {
  // Conservative isotropic scattering: H(1) = 2.9078 (Chandrasekhar 1960, Table XI), and the exact
  // moments int_0^1 H = 2 and int_0^1 mu H = 2 / sqrt(3) (Chandrasekhar 1960, Ch. V).
  const ChandrasekharH h(1.0);
  EXPECT_NEAR(h(1.0), 2.9078, 2e-4);
  EXPECT_NEAR(h(0.0), 1.0, 1e-12);
  const GaussLegendreRule rule = gauss_legendre_rule(40, 0.0, 1.0);
  double moment0 = 0.0, moment1 = 0.0;
  for (size_t i = 0; i < rule.nodes.size(); ++i) {
    moment0 += rule.weights[i] * h(rule.nodes[i]);
    moment1 += rule.weights[i] * rule.nodes[i] * h(rule.nodes[i]);
  }
  EXPECT_NEAR(moment0, 2.0, 1e-4);
  EXPECT_NEAR(moment1, 2.0 / std::sqrt(3.0), 1e-4);
}

TEST(HalfspaceMc, DeterministicForASeedWhateverTheThreadCount) {
  SimulationOptions one, two;
  two.threads = 2;
  const std::vector<Direction> outgoing = {at(0.3, 0.0), at(0.8, 120.0)};
  const GridResult a = simulate_brdf_grid(0.8, at(0.4, 0.0), outgoing, 10'000, 9, one);
  const GridResult b = simulate_brdf_grid(0.8, at(0.4, 0.0), outgoing, 10'000, 9, two);
  const GridResult c = simulate_brdf_grid(0.8, at(0.4, 0.0), outgoing, 10'000, 10, one);
  for (size_t i = 0; i < outgoing.size(); ++i) {
    EXPECT_EQ(a.brdf[i].total.mean, b.brdf[i].total.mean);
    EXPECT_EQ(a.brdf[i].total.standard_error, b.brdf[i].total.standard_error);
    EXPECT_NE(a.brdf[i].total.mean, c.brdf[i].total.mean) << "another seed, other walks";
  }
}

}  // namespace
}  // namespace ochre::halfspace::test::halfspace_mc_test
