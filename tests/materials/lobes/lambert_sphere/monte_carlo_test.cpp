// The LS models against the independent Monte-Carlo half-space simulation (tools/halfspace, exact
// Eq 6 phase sampling): single scattering within noise; the full model within 2 / 4 / 5.5 % for
// c = 0.3 / 0.8 / 0.99; the exact mode within 1 %; cosines >= 0.1. A reduced budget (a few seconds):
// each comparison allows 4 standard errors of the simulation on top of the bound.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "materials/core/pi.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "tools/halfspace/halfspace_mc.h"

namespace ochre::test::monte_carlo_test {
namespace {

struct Case {
  double c;
  double full_bound;
  uint64_t paths;
};

TEST(LambertSphereMonteCarlo, ModelsAgainstTheSimulation) {
  const Case cases[] = {{0.3, 0.02, 200'000}, {0.8, 0.04, 120'000}, {0.99, 0.055, 60'000}};
  const double incidence[] = {0.25, 0.75};
  const double outgoing_mu[] = {0.15, 0.5, 0.9};
  const double outgoing_phi[] = {0.0, 0.5 * kPiD, kPiD};
  std::vector<halfspace::Direction> outgoing;
  for (double mu : outgoing_mu)
    for (double phi : outgoing_phi) outgoing.push_back(halfspace::direction_from_angles(mu, phi));
  const auto t0 = std::chrono::steady_clock::now();
  for (const Case& cs : cases) {
    const LambertSphereConstants<double> k = lambert_sphere_constants(cs.c);
    const LambertSphereExactConstants ke = lambert_sphere_exact_constants(float(cs.c));
    double worst_full = 0, worst_exact = 0, worst_single_sigmas = 0, median_rel_error = 0;
    int n = 0;
    for (double mu_i : incidence) {
      const halfspace::Direction wi = halfspace::direction_from_angles(mu_i, 0.0);
      const halfspace::GridResult mc = halfspace::simulate_brdf_grid(cs.c, wi, outgoing, cs.paths, 1234 + n);
      for (size_t j = 0; j < outgoing.size(); ++j) {
        const halfspace::Direction& wo = outgoing[j];
        const double w = halfspace::dot(wi, wo), mu_o = wo.z;
        const halfspace::HalfspaceResult& r = mc.brdf[j];
        const double single = lambert_sphere_single_scattering(cs.c, mu_i, mu_o, w);
        const double sigmas = std::fabs(r.single.mean - single) / r.single.standard_error;
        worst_single_sigmas = std::max(worst_single_sigmas, sigmas);
        EXPECT_LT(sigmas, 4.5) << "single scattering c " << cs.c << " mu_i " << mu_i << " wo " << j;
        const double ref = r.total.mean, noise = 4 * r.total.standard_error;
        median_rel_error = std::max(median_rel_error, r.total.standard_error / ref);
        const double full = lambert_sphere_full(k, mu_i, mu_o, w);
        const double exact = lambert_sphere_exact(ke, float(mu_i), float(mu_o), float(w));
        worst_full = std::max(worst_full, std::fabs(full / ref - 1));
        worst_exact = std::max(worst_exact, std::fabs(exact / ref - 1));
        EXPECT_LE(std::fabs(full - ref), cs.full_bound * ref + noise)
            << "full c " << cs.c << " mu_i " << mu_i << " wo " << j;
        EXPECT_LE(std::fabs(exact - ref), 0.01 * ref + noise)
            << "exact c " << cs.c << " mu_i " << mu_i << " wo " << j;
      }
      ++n;
    }
    std::printf(
        "MC c = %.2f: full max %.2f %%, exact max %.2f %% (MC standard error up to %.2f %%); single "
        "scattering "
        "within %.1f sigma\n",
        cs.c, 100 * worst_full, 100 * worst_exact, 100 * median_rel_error, worst_single_sigmas);
  }
  std::printf("MC time %.1f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace
}  // namespace ochre::test::monte_carlo_test
