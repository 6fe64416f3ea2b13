// The LS models against the committed Monte-Carlo reference tests/data/halfspace_reference.csv
// (tools/halfspace, 200 000 paths per incidence; the regeneration command is in its header):
// c = 0.3 / 0.8 / 0.99 / 1, mu_i, mu_o in {0.05, 0.1, 0.2, 0.4, 0.6, 0.8, 1}, phi in 0..180 deg.
// Bounds for mu >= 0.1: full 2 / 4 / 5.5 / 5.5 %, exact 1 %, each plus 4 standard errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "materials/core/pi.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "support/test_paths.h"

namespace ochre::test::reference_data_test {
namespace {

struct Row {
  double c, mu_i, mu_o, phi_deg, single, single_se, multiple, multiple_se, total, total_se;
};

std::vector<Row> read_reference() {
  std::ifstream in(ochre::test::source_dir() / "tests/data/halfspace_reference.csv");
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'c') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    Row r;
    if (s >> r.c >> r.mu_i >> r.mu_o >> r.phi_deg >> r.single >> r.single_se >> r.multiple >> r.multiple_se >>
        r.total >> r.total_se)
      rows.push_back(r);
  }
  return rows;
}

struct Worst {
  double full = 0, exact = 0, full_grazing = 0, exact_grazing = 0, single_sigmas = 0, exact_sigmas = 0;
  double rel_se = 0;  // largest relative standard error of the reference (mu >= 0.1)
  int points = 0;
};

TEST(LambertSphereReference, ModelsAgainstTheCommittedSimulation) {
  const std::vector<Row> rows = read_reference();
  if (rows.empty()) GTEST_SKIP() << "tests/data/halfspace_reference.csv not found";
  const std::map<double, double> full_bound = {{0.3, 0.02}, {0.8, 0.04}, {0.99, 0.055}, {1.0, 0.055}};
  std::map<double, Worst> worst;
  for (const Row& r : rows) {
    const auto bound = full_bound.find(r.c);
    if (bound == full_bound.end()) continue;
    const double phi = r.phi_deg * kPiD / 180.0;
    const double w =
        r.mu_i * r.mu_o + std::sqrt((1 - r.mu_i * r.mu_i) * (1 - r.mu_o * r.mu_o)) * std::cos(phi);
    const double single = lambert_sphere_single_scattering(r.c, r.mu_i, r.mu_o, w);
    const double full = lambert_sphere_full(lambert_sphere_constants(r.c), r.mu_i, r.mu_o, w);
    const double exact = lambert_sphere_exact(lambert_sphere_exact_constants(float(r.c)), float(r.mu_i),
                                              float(r.mu_o), float(w));
    Worst& wst = worst[r.c];
    const double sigmas = std::fabs(single - r.single) / r.single_se;
    wst.single_sigmas = std::max(wst.single_sigmas, sigmas);
    EXPECT_LT(sigmas, 5.0) << "single scattering " << r.c << " " << r.mu_i << " " << r.mu_o << " "
                           << r.phi_deg;
    const double e_full = std::fabs(full / r.total - 1), e_exact = std::fabs(exact / r.total - 1);
    if (r.mu_i < 0.1 || r.mu_o < 0.1) {
      wst.full_grazing = std::max(wst.full_grazing, e_full);
      wst.exact_grazing = std::max(wst.exact_grazing, e_exact);
      continue;
    }
    ++wst.points;
    wst.full = std::max(wst.full, e_full);
    wst.exact = std::max(wst.exact, e_exact);
    wst.exact_sigmas = std::max(wst.exact_sigmas, std::fabs(exact - r.total) / r.total_se);
    wst.rel_se = std::max(wst.rel_se, r.total_se / r.total);
    const double noise = 4 * r.total_se;
    EXPECT_LE(std::fabs(full - r.total), bound->second * r.total + noise)
        << "full " << r.c << " " << r.mu_i << " " << r.mu_o << " " << r.phi_deg;
    EXPECT_LE(std::fabs(exact - r.total), 0.01 * r.total + noise)
        << "exact " << r.c << " " << r.mu_i << " " << r.mu_o << " " << r.phi_deg;
  }
  for (const auto& [c, wst] : worst) {
    std::printf(
        "reference c = %.2f (%d points, mu >= 0.1): full %.2f %%, exact %.2f %%; with mu = 0.05: full %.2f "
        "%%, "
        "exact %.2f %%; exact within %.1f sigma, single scattering within %.1f sigma (reference standard "
        "error "
        "up to %.2f %%)\n",
        c, wst.points, 100 * wst.full, 100 * wst.exact, 100 * wst.full_grazing, 100 * wst.exact_grazing,
        wst.exact_sigmas, wst.single_sigmas, 100 * wst.rel_se);
    EXPECT_GT(wst.points, 100);
  }
}

}  // namespace
}  // namespace ochre::test::reference_data_test
