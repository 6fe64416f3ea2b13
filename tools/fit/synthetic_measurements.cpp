#include "tools/fit/synthetic_measurements.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "tools/fit/powder_fit_model.h"
#include "tools/halfspace/random_source.h"

namespace ochre {

std::vector<Measurement> goniophotometer_grid(const std::vector<double>& lambdas_nm) {
  std::vector<Measurement> grid;
  for (double lambda : lambdas_nm)
    for (int theta_i : {0, 20, 40, 60}) {
      std::set<std::pair<int, int>> seen;  // (theta_o, phi_o), phi_o = 0 at the normal
      const auto add = [&](int signed_theta, int plane) {
        const int theta_o = std::abs(signed_theta);
        const int phi_o = theta_o == 0 ? 0 : signed_theta < 0 ? plane : plane + 180;
        if (!seen.insert({theta_o, phi_o}).second) return;
        Measurement m;
        m.theta_i = theta_i;
        m.theta_o = theta_o;
        m.phi_o = phi_o;
        m.lambda_nm = lambda;
        m.wi = direction_from_angles(m.theta_i, m.phi_i);
        m.wo = direction_from_angles(m.theta_o, m.phi_o);
        grid.push_back(m);
      };
      for (int plane : {0, 30, 60, 90, 135})
        for (int t = -70; t <= 70; t += 10) add(t, plane);
      for (int t = theta_i - 10; t <= theta_i + 10; t += 2) add(-t, 0);
    }
  return grid;
}

void synthesize_brdf(std::vector<Measurement>& grid, const PowderValues& values, const FitPigment& pigment,
                     double noise, uint64_t seed) {
  const std::vector<double> brdf = powder_brdf_values(values, grid, pigment);
  halfspace::RandomSource random(seed, 0);
  for (size_t i = 0; i < grid.size(); ++i) {
    const double u1 = 1.0 - random.uniform(), u2 = random.uniform();  // u1 in (0, 1]
    const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    // Clamped: a draw below -1 / noise (5 sigma at noise 0.2) would make a negative BRDF, which no
    // measurement file may hold.
    grid[i].brdf = std::max(0.0, brdf[i] * (1.0 + noise * z));
  }
}

}  // namespace ochre
