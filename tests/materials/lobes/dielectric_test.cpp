// Dielectric lobes: the smooth (delta) interface with reflection and refraction from both sides, the
// opaque (black glass) variant, and GGX reflection only. Physical checks of the Mueller frames
// (Brewster), R + T = 1, chi-square of the rough lobe, hard cases, and the closure node.

#include "materials/lobes/dielectric.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "materials/chi2_test.h"
#include "materials/core/pcg32.h"
#include "materials/graph/graph_error.h"
#include "materials/lobes/fresnel.h"
#include "materials/material_test_support.h"
#include "materials/polarization_test_support.h"

namespace ochre::test::dielectric_test {
namespace {

TEST(SmoothDielectric, ReflectionAndRefractionProbabilitiesSumToOneOnBothSides) {
  for (float eta : {1.5f, 1.33f, 2.4f}) {
    const SmoothDielectricLobe lobe(eta, false);
    for (float side : {1.0f, -1.0f})
      for (int i = 1; i <= 100; ++i) {
        const float c = i / 100.0f;
        const Vec3 wo(std::sqrt(1 - c * c), 0.0f, side * c);
        const auto r = lobe.sample(wo, 0.0f, {0, 0}, test_wavelengths());
        const auto t = lobe.sample(wo, 0.999999f, {0, 0}, test_wavelengths());
        ASSERT_TRUE(r && t);
        const bool r_reflects = r->wi.z * wo.z > 0, t_reflects = t->wi.z * wo.z > 0;
        EXPECT_TRUE(r_reflects);
        const float R = r->pdf, T = t_reflects ? 0.0f : t->pdf;  // TIR: both draws reflect
        EXPECT_NEAR(R + T, 1.0f, 1e-6f) << eta << " " << side * c;
        EXPECT_NEAR(R, fresnel_dielectric(side * c, eta), 1e-6f);
        // Unbiased weights: E[weight] = R * 1 + T * (n_o / n_i)^2.
        EXPECT_NEAR(r->weight[0], 1.0f, 1e-5f);
        if (!t_reflects) {
          const float n_ratio = side > 0 ? 1 / eta : eta;
          EXPECT_NEAR(t->weight[0], n_ratio * n_ratio, 1e-5f * n_ratio * n_ratio) << eta << " " << side * c;
          // Snell: n_o sin_o = n_i sin_i, and the refracted ray is on the other side.
          const float sin_o = std::sqrt(1 - wo.z * wo.z), sin_i = std::sqrt(1 - t->wi.z * t->wi.z);
          EXPECT_NEAR(sin_i, sin_o * n_ratio, 1e-5f);
          EXPECT_LT(t->wi.z * wo.z, 0.0f);
          EXPECT_NEAR(length(t->wi), 1.0f, 1e-6f);
        }
      }
  }
}

TEST(SmoothDielectric, TotalInternalReflectionInside) {
  const SmoothDielectricLobe lobe(1.5f, false);
  const Vec3 wo = direction(kPi - 0.9f, 0.2f);  // inside, beyond the critical angle asin(1/1.5) = 0.73
  const auto s = lobe.sample(wo, 0.999f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(s);
  EXPECT_EQ(s->pdf, 1.0f);
  EXPECT_LT(s->wi.z, 0.0f);
  EXPECT_NEAR(s->weight[0], 1.0f, 1e-6f);
  // The TIR retardance of the note's matrix is present (|r_s| = |r_p| = 1, Delta != 0).
  const Mueller want = specular_reflection(std::cos(0.9f), 1 / 1.5f);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(s->mueller.m[0](r, c), want(r, c), 1e-6f);
}

// Physical test (2): at Brewster's angle the reflected light is purely s-polarized (S1 = +S0 in the
// lobe frames, x = s), and p-polarized light, built from world geometry alone, is not reflected.
TEST(SmoothDielectric, BrewsterReflectionIsSPolarized) {
  for (float eta : {1.5f, 1 / 1.5f}) {
    const SmoothDielectricLobe lobe(eta, false);
    const float theta_b = std::atan(eta);
    // eta = 1/1.5 is the Brewster reflection of light arriving from the denser side.
    const Vec3 wo = direction(theta_b, 0.6f);
    const auto s = lobe.sample(wo, 0.0f, {0, 0}, test_wavelengths());
    ASSERT_TRUE(s);
    const Mueller m = s->mueller.m[0] * s->pdf;  // undo the 1 / probability
    const Stokes out = m * Stokes::unpolarized(1.0f);
    EXPECT_GT(out[0], 0.01f);
    EXPECT_NEAR(out[1], out[0], 1e-6f);
    EXPECT_NEAR(out[2], 0.0f, 1e-6f);
    EXPECT_NEAR(out[3], 0.0f, 1e-6f);
    // s is the world direction perpendicular to the plane of incidence.
    const Vec3 d_in = -s->wi;
    const Vec3 plane_normal = normalize(cross(Vec3(0, 0, 1), d_in));
    EXPECT_NEAR(std::fabs(dot(s->mueller.in_x, plane_normal)), 1.0f, 1e-6f);
    // p light: the field in the plane of incidence, perpendicular to the beam.
    const Vec3 p_field = normalize(cross(plane_normal, d_in));
    const Stokes p_out = m * linear_stokes(p_field, d_in, s->mueller.in_x);
    EXPECT_NEAR(p_out[0], 0.0f, 1e-6f);
    const Stokes s_out = m * linear_stokes(plane_normal, d_in, s->mueller.in_x);
    EXPECT_NEAR(s_out[0], 2 * out[0], 1e-6f);
    // The reflected s light oscillates along the same world direction.
    const Vec3 e = polarization_direction(s_out, wo, s->mueller.out_x);
    EXPECT_NEAR(std::fabs(dot(e, plane_normal)), 1.0f, 1e-5f);
  }
}

TEST(SmoothDielectric, RefractionMuellerIsTheNotesTransmissionMatrix) {
  const float eta = 1.5f;
  const SmoothDielectricLobe lobe(eta, false);
  // wo outside; the light comes from inside along -wi: the transmission from inside at wi's angle.
  const Vec3 wo = direction(1.0f, 0.3f);
  const auto t = lobe.sample(wo, 0.9999f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(t);
  ASSERT_LT(t->wi.z, 0.0f);
  const Mueller want = specular_transmission(t->wi.z, eta) * (1 / (eta * eta) / t->pdf);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(t->mueller.m[0](r, c), want(r, c), 1e-6f);
  EXPECT_TRUE(valid_frames(t->mueller, wo, t->wi));
  // Brewster from inside: the note's matrix.
  const float theta_inside = std::atan(1 / 1.5f);
  const Mueller brewster = specular_transmission(-std::cos(theta_inside), eta);
  EXPECT_NEAR(brewster(0, 0), 0.9260355f, 2e-6f);
  EXPECT_NEAR(brewster(0, 1), -0.07396451f, 2e-6f);
  EXPECT_NEAR(brewster(2, 2), 0.92307705f, 2e-6f);
}

TEST(SmoothDielectric, OpaqueAbsorbsTheRefractedPart) {
  const SmoothDielectricLobe black_glass(1.5f, true);
  EXPECT_EQ(black_glass.flags() & kLobeTransmission, 0u);
  for (float u : {0.0f, 0.5f, 0.99f}) {
    const Vec3 wo = direction(0.7f, 0.0f);
    const auto s = black_glass.sample(wo, u, {0, 0}, test_wavelengths());
    ASSERT_TRUE(s);
    EXPECT_GT(s->wi.z, 0.0f);
    EXPECT_EQ(s->pdf, 1.0f);
    EXPECT_NEAR(s->weight[0], fresnel_dielectric(wo.z, 1.5f), 1e-7f);
  }
  EXPECT_NEAR(black_glass.sample(Vec3(0, 0, 1), 0.5f, {0, 0}, test_wavelengths())->weight[0], 0.04f, 1e-6f);
  EXPECT_FALSE(black_glass.sample(direction(2.5f, 0.0f), 0.5f, {0, 0}, test_wavelengths()));
}

TEST(SmoothDielectric, HardCases) {
  const SmoothDielectricLobe glass(1.5f, false), air(1.0f, false);
  for (float c : {1.0f, 1e-7f, -1e-7f, -1.0f}) {
    const Vec3 wo(std::sqrt(1 - c * c), 0.0f, c);
    for (float u : {0.0f, 0.5f, 0.999f}) {
      const auto s = glass.sample(wo, u, {0, 0}, test_wavelengths());
      ASSERT_TRUE(s) << c;
      EXPECT_TRUE(all_finite(s->weight));
      EXPECT_TRUE(all_finite(s->mueller.m[0]));
      EXPECT_TRUE(std::isfinite(length(s->wi)));
    }
  }
  // eta = 1: no reflection; the ray passes straight through with weight 1.
  const Vec3 wo = direction(0.4f, 1.0f);
  const auto s = air.sample(wo, 0.0f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
  EXPECT_NEAR(s->wi.z, -wo.z, 1e-6f);
  EXPECT_NEAR(s->weight[0], 1.0f, 1e-6f);
  EXPECT_FALSE(glass.sample(Vec3(1, 0, 0), 0.0f, {0, 0}, test_wavelengths())) << "exactly grazing";
}

TEST(RoughDielectric, ReflectsWithTheDielectricFresnelOnly) {
  const RoughDielectricLobe lobe(1.5f, 0.2f);
  EXPECT_EQ(lobe.flags() & kLobeTransmission, 0u);
  Pcg32 rng(4);
  for (int i = 0; i < 500; ++i) {
    const Vec3 wo = direction(std::acos(rng.next_float()), 2 * kPi * rng.next_float());
    const Vec3 wi = direction(std::acos(rng.next_float()), 2 * kPi * rng.next_float());
    const MuellerResponse r = lobe.eval_mueller(wo, wi, test_wavelengths());
    EXPECT_NEAR(r.m[1](0, 0), lobe.eval(wo, wi, test_wavelengths())[1], 1e-6f);
    EXPECT_TRUE(valid_frames(r, wo, wi));
    EXPECT_TRUE(lobe.eval(wo, -wi, test_wavelengths()).is_black());
  }
  // Albedo is below the Fresnel maximum: a rough black glass reflects a few percent.
  const Vec3 wo = direction(0.2f, 0.0f);
  double sum = 0;
  for (int i = 0; i < 20000; ++i)
    if (const auto s = lobe.sample(wo, 0.0f, {rng.next_float(), rng.next_float()}, test_wavelengths()))
      sum += s->weight[0];
  EXPECT_NEAR(sum / 20000, 0.04, 0.01);
}

TEST(RoughDielectric, ChiSquareOfSampleAgainstPdf) {
  const float cases[][2] = {{0.1f, 0.4f}, {0.3f, 0.0f}, {0.6f, 1.3f}, {1.0f, 1.55f}, {0.3f, 1.5f}};
  const double significance = sidak_significance(0.01, int(std::size(cases)));
  int seed = 300;
  for (const auto& c : cases) {
    const RoughDielectricLobe lobe(1.5f, c[0]);
    const Chi2Result r = chi2_test(lobe, direction(c[1], 2.0f), test_wavelengths(), 40, 80, 300'000, seed++);
    SCOPED_TRACE(r.summary());
    std::printf("rough dielectric alpha %g theta %g: %s\n", c[0], c[1], r.summary().c_str());
    EXPECT_GT(r.p_value, significance);
    EXPECT_EQ(r.weight_mismatches, 0);
    EXPECT_EQ(r.pdf_mismatches, 0);
    EXPECT_EQ(r.samples_in_empty_cells, 0);
  }
}

TEST(RoughDielectric, HardCasesGiveNoNaN) {
  for (float alpha : {1e-4f, 1.0f}) {
    const RoughDielectricLobe lobe(1.5f, alpha);
    Pcg32 rng(2);
    for (float c : {1.0f, 1e-7f}) {
      const Vec3 wo(std::sqrt(1 - c * c), 0.0f, c);
      for (int i = 0; i < 500; ++i)
        if (const auto s = lobe.sample(wo, 0.0f, {rng.next_float(), rng.next_float()}, test_wavelengths())) {
          EXPECT_TRUE(all_finite(s->weight));
          EXPECT_TRUE(all_finite(s->mueller.m[0]));
        }
      EXPECT_TRUE(all_finite(lobe.eval(wo, Vec3(-wo.x, -wo.y, wo.z), test_wavelengths())));
    }
  }
}

// ---------------------------------------------------------------- the closure node

TEST(DielectricNode, SmoothRoughAndOpaque) {
  ShadingContext ctx;
  ctx.lambda = &test_wavelengths();
  LobeArena arena;
  auto lobe_of = [&](const char* json, Closure& c) -> const Lobe* {
    auto m = compile(json);
    m->evaluate(ctx, arena, c);
    EXPECT_TRUE(m->facts().polarizes) << json;
    return c.lobe_count() == 1 ? c.lobe(0).lobe : nullptr;
  };
  Closure a, b, c;
  const Lobe* glass = lobe_of(R"({"type": "dielectric"})", a);
  ASSERT_TRUE(glass);
  EXPECT_NE(glass->flags() & kLobeTransmission, 0u);
  EXPECT_NEAR(glass->sample(Vec3(0, 0, 1), 0.0f, {0, 0}, test_wavelengths())->pdf, 0.04f, 1e-6f);
  const Lobe* black = lobe_of(R"({"type": "dielectric", "ior": 1.5, "opaque": 1})", b);
  ASSERT_TRUE(black);
  EXPECT_EQ(black->flags() & kLobeTransmission, 0u);
  const Lobe* rough = lobe_of(R"({"type": "dielectric", "ior": 1.33, "roughness": 0.2})", c);
  ASSERT_TRUE(rough);
  EXPECT_NE(rough->flags() & kLobeGlossy, 0u);
  EXPECT_THROW(compile(R"({"type": "dielectric", "ior": 0})"), GraphError);
  EXPECT_THROW(compile(R"({"type": "dielectric", "opaque": 2})"), GraphError);
  EXPECT_THROW(compile(R"({"type": "dielectric", "opaque": true})"), GraphError);
}

}  // namespace
}  // namespace ochre::test::dielectric_test
