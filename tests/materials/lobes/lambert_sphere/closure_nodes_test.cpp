// The closure nodes lambert_sphere, oren_nayar and chandrasekhar compiled from JSON and evaluated.

#include <gtest/gtest.h>

#include "materials/graph/compiled_material.h"
#include "materials/lobes/chandrasekhar_halfspace.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/lobes/oren_nayar.h"
#include "support/spectrum_lanes.h"
#include "support/test_material.h"

namespace ochre::test::closure_nodes_test {
namespace {

const SampledWavelengths& wavelengths() {
  static const SampledWavelengths lambda = SampledWavelengths::fixed(lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  return lambda;
}

// Evaluates the material's closure at (wo, wi).
SampledSpectrum evaluate(const std::string& json, const Vec3& wo, const Vec3& wi) {
  const auto material = compile_test_material(json);
  ShadingContext ctx;
  ctx.lambda = &wavelengths();
  LobeArena arena;
  Closure closure;
  material->evaluate(ctx, arena, closure);
  EXPECT_EQ(closure.lobe_count(), 1) << json;
  return closure.eval(wo, wi, wavelengths());
}

const Vec3 kWo = normalize(Vec3(0.3f, 0.1f, 0.8f));
const Vec3 kWi = normalize(Vec3(-0.5f, 0.2f, 0.4f));

TEST(LambertSphereNode, KdIsMappedToTheParticleAlbedo) {
  const SampledSpectrum f = evaluate(R"({"type": "lambert_sphere", "kd": 0.5})", kWo, kWi);
  const float c = lambert_sphere_c_from_kd(0.5f);
  EXPECT_FLOAT_EQ(f[0], lambert_sphere_full(lambert_sphere_constants(c), kWi.z, kWo.z, dot(kWi, kWo)));
  const SampledSpectrum f46 =
      evaluate(R"({"type": "lambert_sphere", "kd": 0.5, "mapping": "eq46"})", kWo, kWi);
  const float c46 = lambert_sphere_c_from_kd_eq46(0.5f);
  EXPECT_FLOAT_EQ(f46[0], lambert_sphere_full(lambert_sphere_constants(c46), kWi.z, kWo.z, dot(kWi, kWo)));
  EXPECT_GT(f46[0], f[0]) << "Eq 46 maps kd to a larger c";
}

TEST(LambertSphereNode, ParticleAlbedoAndVariants) {
  const float mu_i = kWi.z, mu_o = kWo.z, w = dot(kWi, kWo);
  const LambertSphereConstants<float> k = lambert_sphere_constants(0.7f);
  EXPECT_FLOAT_EQ(evaluate(R"({"type": "lambert_sphere", "particle_albedo": 0.7})", kWo, kWi)[1],
                  lambert_sphere_full(k, mu_i, mu_o, w));
  EXPECT_FLOAT_EQ(
      evaluate(R"({"type": "lambert_sphere", "particle_albedo": 0.7, "variant": "fast"})", kWo, kWi)[2],
      lambert_sphere_fast(k, mu_i, mu_o, w));
  EXPECT_FLOAT_EQ(
      evaluate(R"({"type": "lambert_sphere", "particle_albedo": 0.7, "variant": "exact"})", kWo, kWi)[3],
      lambert_sphere_exact(lambert_sphere_exact_constants(0.7f), mu_i, mu_o, w));
  EXPECT_ANY_THROW(compile_test_material(R"({"type": "lambert_sphere", "variant": "slow"})"));
}

TEST(LambertSphereNode, OrenNayarAndChandrasekhar) {
  EXPECT_FLOAT_EQ(evaluate(R"({"type": "oren_nayar", "color": 0.5, "sigma": 0.4})", kWo, kWi)[0],
                  0.5f * OrenNayarLobe(0.4f).value(kWo, kWi));
  EXPECT_FLOAT_EQ(evaluate(R"({"type": "chandrasekhar", "albedo": 0.9})", kWo, kWi)[0],
                  chandrasekhar_brdf(chandrasekhar_constants(0.9f), kWi.z, kWo.z));
}

}  // namespace
}  // namespace ochre::test::closure_nodes_test
