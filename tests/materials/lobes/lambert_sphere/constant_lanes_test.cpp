// The lobe's c-dependent constants, computed in single precision for all the wavelengths at once (branchless
// exp and log, vectorized), give the BRDF of the constants computed in double precision, and each lane is the
// scalar single-precision function's value.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_constant_lanes.h"

namespace ochre::constant_lanes_test {
namespace {

constexpr double kAlbedos[] = {0.0,  1e-6, 0.01, 0.1,  0.25,  0.3,      0.5,
                               0.77, 0.8,  0.9,  0.99, 0.999, 0.999999, 1.0};

// The constants of c in lane 3 of a spectrum whose other lanes hold other albedos.
LambertSphereConstants<float> lane_constants(double c) {
  SampledSpectrum albedos;
  for (int k = 0; k < kSpectrumSamples; ++k) albedos[k] = static_cast<float>(kAlbedos[k]);
  albedos[3] = static_cast<float>(c);
  return lambert_sphere_constant_lanes(albedos.lanes()).at(3);
}

TEST(LambertSphereConstantLanes, SinglePrecisionConstantsGiveTheDoublePrecisionBrdf) {
  double worst_full = 0.0, worst_fast = 0.0;
  const double mus[] = {0.02, 0.1, 0.3, 0.6, 0.9, 1.0};
  for (double c : kAlbedos) {
    const LambertSphereConstants<double> direct = lambert_sphere_constants(c);
    const LambertSphereConstants<float> lanes = lane_constants(c);
    for (double mu_i : mus)
      for (double mu_o : mus)
        for (double phi : {0.0, 1.0, 2.0, 3.14159}) {
          const double s = std::sqrt((1 - mu_i * mu_i) * (1 - mu_o * mu_o));
          const double dot = mu_i * mu_o + s * std::cos(phi);
          const LambertSphereGeometry<double> gd = lambert_sphere_geometry(mu_i, mu_o, dot);
          const LambertSphereGeometry<float> gf = lambert_sphere_geometry(
              static_cast<float>(mu_i), static_cast<float>(mu_o), static_cast<float>(dot));
          // Relative to the BRDF, or to 1e-3 (1/sr) where it is smaller: at c near 0 the fitted constants
          // leave a floor of ~5e-6 that float rounding alone changes by a few %.
          const double full_d = lambert_sphere_full(direct, gd), full_f = lambert_sphere_full(lanes, gf);
          worst_full = std::max(worst_full, std::fabs(full_f - full_d) / std::max(full_d, 1e-3));
          const double fast_d = lambert_sphere_fast(direct, gd, lambert_sphere_fast_factor(mu_i, mu_o, dot));
          const double fast_f = lambert_sphere_fast(
              lanes, gf,
              lambert_sphere_fast_factor(static_cast<float>(mu_i), static_cast<float>(mu_o),
                                         static_cast<float>(dot)));
          worst_fast = std::max(worst_fast, std::fabs(fast_f - fast_d) / std::max(fast_d, 1e-3));
        }
  }
  std::printf(
      "single-precision lanes vs double: max relative BRDF difference (floor 1e-3/sr) full %.2e, fast %.2e\n",
      worst_full, worst_fast);
  EXPECT_LT(worst_full, 5e-5);  // 2.9e-5 (the interpolated table this replaced: 1.6e-4)
  // The fast variant's float evaluation differs from double by ~1e-3 by itself (Eq 48's acos near S = 1).
  EXPECT_LT(worst_fast, 2e-3);
}

TEST(LambertSphereConstantLanes, EveryLaneIsTheScalarFunction) {
  for (double c : kAlbedos) {
    const LambertSphereConstants<float> lanes = lane_constants(c),
                                        scalar = lambert_sphere_constants(float(c));
    const float l[] = {lanes.c,
                       lanes.h0_a,
                       lanes.h0_d,
                       lanes.inv_h0_infinity,
                       lanes.A,
                       lanes.B,
                       lanes.C,
                       lanes.D,
                       lanes.E,
                       lanes.F,
                       lanes.ln_h1_at_one,
                       lanes.l,
                       lanes.l2_plus_45m_over_64,
                       lanes.fast_constant,
                       lanes.fast_slope};
    const float s[] = {scalar.c,
                       scalar.h0_a,
                       scalar.h0_d,
                       scalar.inv_h0_infinity,
                       scalar.A,
                       scalar.B,
                       scalar.C,
                       scalar.D,
                       scalar.E,
                       scalar.F,
                       scalar.ln_h1_at_one,
                       scalar.l,
                       scalar.l2_plus_45m_over_64,
                       scalar.fast_constant,
                       scalar.fast_slope};
    for (int i = 0; i < 15; ++i) EXPECT_EQ(l[i], s[i]) << "c = " << c << ", constant " << i;
  }
}

// The lanes run as vector instructions (eight or four lanes per instruction, whichever the processor has)
// and this test's scalar calls one lane at a time: the same operations in the same order, so the same bits.
TEST(LambertSphereConstantLanes, FullModelLanesAreTheScalarFunction) {
  SampledSpectrum albedos;
  for (int k = 0; k < kSpectrumSamples; ++k) albedos[k] = static_cast<float>(kAlbedos[2 * k % 14]);
  const LambertSphereConstantLanes lanes = lambert_sphere_constant_lanes(albedos.lanes(), false);
  for (float mu_i : {0.001f, 0.3f, 0.71f, 1.0f})
    for (float mu_o : {0.02f, 0.5f, 0.99f})
      for (float cos_phi : {-1.0f, 0.0f, 0.6f}) {
        const float dot = mu_i * mu_o + std::sqrt((1 - mu_i * mu_i) * (1 - mu_o * mu_o)) * cos_phi;
        const LambertSphereGeometry<float> g = lambert_sphere_geometry(mu_i, mu_o, dot);
        SampledSpectrum f;
        lambert_sphere_full_lanes(lanes, g, f.lanes());
        for (int k = 0; k < kSpectrumSamples; ++k) {
          EXPECT_EQ(f[k], lambert_sphere_full(lambert_sphere_constants(albedos[k], false), g)) << k;
          EXPECT_GT(f[k], 0.0f);
        }
      }
}

}  // namespace
}  // namespace ochre::constant_lanes_test
