// The committed exact-mode table (materials/lobes/lambert_sphere/lambert_sphere_exact_data.cpp) against a
// fresh doubling solution. The table's generator is tools/data/make_lambert_sphere_exact_table.cpp
// (docs/tools.md, "Data generators").

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"

namespace ochre::test::exact_table_test {
namespace {

// Grid of the committed table (the generator's): 25 x 25 cosines (uniform in x = mu^(1/3)), 25 albedos
// (s = sqrt(1 - c)): 0.28 % interpolation error for mu >= 0.1 (docs/materials/lambert_sphere.md).
constexpr int kXNodes = 25;
constexpr int kSNodes = 25;

TEST(LambertSphereExactTable, CommittedTableMatchesAFreshSolution) {
  const LambertSphereExactGrid& grid = lambert_sphere_exact_grid();
  ASSERT_EQ(grid.x_nodes, kXNodes);
  ASSERT_EQ(grid.s_nodes, kSNodes);
  EXPECT_EQ(lambert_sphere_exact_bytes(), grid.size() * sizeof(float));
  // One albedo slice near c = 0.9 (~0.4 s): every stored value to 1e-5 relative (or 1e-7 absolute).
  const int s = 8;
  const std::vector<float> fresh = compute_lambert_sphere_exact_slice(grid, s);
  const float* stored = lambert_sphere_exact_data() + grid.index(s, 0, 0, 0);
  int mismatches = 0;
  for (size_t k = 0; k < fresh.size(); ++k)
    if (std::fabs(fresh[k] - stored[k]) > 1e-5f * std::fabs(fresh[k]) + 1e-7f) ++mismatches;
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace ochre::test::exact_table_test
