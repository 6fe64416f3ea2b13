// Every table lookup and lobe parameter of materials/ given NaN, +-inf and huge values: indices stay in
// their tables and the results are finite (docs/nodes.md, "Non-finite values"; the values reaching them
// in a render are already finite, these are the second line of defence).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "materials/core/pcg32.h"
#include "materials/lobes/chandrasekhar_halfspace.h"
#include "materials/lobes/conductor.h"
#include "materials/lobes/dielectric.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_constant_lanes.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "materials/lobes/oren_nayar.h"
#include "materials/numerics/h_function.h"
#include "support/awkward_floats.h"
#include "support/spectrum_lanes.h"

using ochre::test::lanes;

namespace ochre::non_finite_lookups_test {
namespace {

using test::awkward_floats;
using test::kInf;
using test::kNaN;

template <class T>
void expect_finite_constants(const LambertSphereConstants<T>& k, float c) {
  for (T v : {k.c, k.h0_a, k.h0_d, k.inv_h0_infinity, k.A, k.B, k.C, k.D, k.E, k.F, k.ln_h1_at_one, k.l,
              k.l2_plus_45m_over_64, k.fast_constant, k.fast_slope})
    EXPECT_TRUE(std::isfinite(v)) << "c = " << c;
  EXPECT_TRUE(k.c >= 0 && k.c <= 1) << "c = " << c;
}

TEST(NonFiniteLookups, LambertSphereConstants) {
  for (float c : awkward_floats()) {
    expect_finite_constants(lambert_sphere_constant_lanes(SampledSpectrum(c).lanes()).at(0), c);
    expect_finite_constants(lambert_sphere_constants(c), c);
    expect_finite_constants(lambert_sphere_constants(static_cast<double>(c)), c);
    EXPECT_TRUE(std::isfinite(lambert_sphere_kd_from_c_eq47(c))) << c;
    EXPECT_TRUE(std::isfinite(lambert_sphere_c_from_kd_eq46(c))) << c;
  }
  EXPECT_EQ(lambert_sphere_constant_lanes(SampledSpectrum(kNaN).lanes()).at(0).c, 0.0f);  // NaN counts as 0
}

TEST(NonFiniteLookups, LambertSphereExactTableIndices) {
  const LambertSphereExactGrid& grid = lambert_sphere_exact_grid();
  for (float c : awkward_floats()) {
    const LambertSphereExactConstants k = lambert_sphere_exact_constants(c);
    EXPECT_TRUE(k.s_index >= 0 && k.s_index <= grid.s_nodes - 2) << c;
    EXPECT_TRUE(k.s_weight >= 0.0f && k.s_weight <= 1.0f) << c;
    for (float mu : awkward_floats()) {
      const LambertSphereExactGeometry g = lambert_sphere_exact_geometry(mu, 0.5f, 0.3f);
      if (!g.valid) continue;  // NaN and mu <= 0
      EXPECT_TRUE(g.i >= 0 && g.i <= grid.x_nodes - 2) << mu;
      if (mu <= 1.0f) {  // a cosine above 1 is no direction: only the index must hold there
        EXPECT_TRUE(std::isfinite(lambert_sphere_exact_multiple_scattering(k, g))) << mu;
      }
    }
  }
}

TEST(NonFiniteLookups, BondAlbedoInverses) {
  for (float kd : awkward_floats())
    for (const BondAlbedoInverse* inverse :
         {&lambert_sphere_kd_inverse(), &lambert_sphere_exact_kd_inverse()}) {
      const float c = inverse->c(kd);
      EXPECT_TRUE(c >= 0.0f && c <= 1.0f) << kd;
      EXPECT_TRUE(std::isfinite(inverse->weight_scale(kd))) << kd;
    }
}

TEST(NonFiniteLookups, ChandrasekharTable) {
  for (float c : awkward_floats()) {
    const ChandrasekharConstants k = chandrasekhar_constants(c);
    EXPECT_TRUE(k.c >= 0.0f && k.c <= 1.0f) << c;
    EXPECT_TRUE(k.s_weight >= 0.0f && k.s_weight <= 1.0f) << c;
    for (float mu : awkward_floats()) {
      EXPECT_TRUE(std::isfinite(chandrasekhar_h(k, mu))) << c << " " << mu;
      EXPECT_TRUE(std::isfinite(chandrasekhar_brdf(k, mu, 0.5f))) << c << " " << mu;
    }
  }
}

TEST(NonFiniteLookups, ExactHFunctions) {
  const std::vector<double> values = {std::nan(""), HUGE_VAL, -HUGE_VAL, 1e30, -1e30};
  for (double mu : values)
    for (double c : {0.5, std::nan(""), HUGE_VAL, -HUGE_VAL, 1e30}) {
      for (int mode = 0; mode < 3; ++mode)
        EXPECT_TRUE(std::isfinite(lambert_sphere_h_exact(mode, mu, c))) << mode << " " << mu << " " << c;
      EXPECT_TRUE(std::isfinite(isotropic_h_exact(mu, c))) << mu << " " << c;
    }
  for (double t : values) EXPECT_FALSE(std::isinf(h_dispersion(isotropic_characteristic(0.5), t))) << t;
}

// A lobe built from `albedo_or_roughness` must evaluate and sample to finite values in every direction.
void expect_finite_lobe(const Lobe& lobe, float parameter) {
  const SampledWavelengths lambda = SampledWavelengths::fixed(lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  Pcg32 rng(11);
  for (int n = 0; n < 64; ++n) {
    const Vec3 wo = normalize(Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float()));
    const Vec3 wi =
        normalize(Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.2f));
    EXPECT_TRUE(lobe.eval(wo, wi, lambda).is_finite()) << parameter;
    EXPECT_TRUE(std::isfinite(lobe.pdf(wo, wi, lambda))) << parameter;
    EXPECT_TRUE(lobe.albedo_hint(wo, lambda).is_finite()) << parameter;
    const auto s = lobe.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()}, lambda);
    if (!s) continue;
    EXPECT_TRUE(s->weight.is_finite()) << parameter;
    EXPECT_TRUE(std::isfinite(s->pdf)) << parameter;
    EXPECT_TRUE(std::isfinite(s->wi.x) && std::isfinite(s->wi.y) && std::isfinite(s->wi.z)) << parameter;
  }
}

TEST(NonFiniteLookups, LobesBuiltFromNonFiniteParameters) {
  const SampledSpectrum copper_n = lanes({0.27f, 1.1f, 1.2f, 0.2f}),
                        copper_k = lanes({3.4f, 2.6f, 2.4f, 4.0f});
  for (float x : awkward_floats()) {
    const SampledSpectrum s(x);
    for (LambertSphereVariant v :
         {LambertSphereVariant::kFull, LambertSphereVariant::kFast, LambertSphereVariant::kExact})
      expect_finite_lobe(LambertSphereLobe(v, s), x);
    expect_finite_lobe(ChandrasekharLobe(s), x);
    expect_finite_lobe(OrenNayarLobe(x), x);
    expect_finite_lobe(RoughConductorLobe(copper_n, copper_k, x), x);
    expect_finite_lobe(RoughDielectricLobe(1.5f, x), x);
  }
}

}  // namespace
}  // namespace ochre::non_finite_lookups_test
