// Conductor lobes: smooth (delta) and GGX-rough reflection off a metal, polarized through the Fresnel
// Mueller matrix. Physical checks of the Mueller frames, chi-square of the rough lobe's sampling, the
// white furnace (single-scattering energy loss printed), hard numerical cases, and the closure node.

#include "materials/lobes/conductor.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "materials/chi2_test.h"
#include "materials/core/pcg32.h"
#include "materials/graph/graph_error.h"
#include "materials/lobes/fresnel.h"
#include "materials/material_test_support.h"
#include "materials/polarization_test_support.h"
#include "spectra/named_spectra.h"
#include "support/spectrum_lanes.h"

namespace ochre::test::conductor_test {
namespace {

const SampledSpectrum kSilverN(0.136125f), kSilverK(4.010625f);

TEST(SmoothConductor, MirrorsWithTheFresnelReflectance) {
  const SmoothConductorLobe lobe(lanes({0.2f, 0.5f, 1.2f, 4.073f}), lanes({3.0f, 2.5f, 7.0f, 0.028f}));
  for (float theta : {0.0f, 0.3f, 1.0f, 1.5f}) {
    const Vec3 wo = direction(theta, 0.7f);
    const auto s = lobe.sample(wo, 0.5f, {0.3f, 0.3f}, test_wavelengths());
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
    EXPECT_TRUE(s->has_mueller);
    EXPECT_EQ(s->pdf, 1.0f);
    EXPECT_NEAR(s->wi.x, -wo.x, 1e-7f);
    EXPECT_NEAR(s->wi.y, -wo.y, 1e-7f);
    EXPECT_NEAR(s->wi.z, wo.z, 1e-7f);
    const float n[] = {0.2f, 0.5f, 1.2f, 4.073f},
                k[] = {3.0f, 2.5f, 7.0f, 0.028f};  // repeated across the lanes
    for (int i = 0; i < kSpectrumSamples; ++i) {
      EXPECT_NEAR(s->weight[i], fresnel_conductor(wo.z, n[i % 4], k[i % 4]), 1e-6f);
      EXPECT_FLOAT_EQ(s->mueller.m[i](0, 0), s->weight[i]);
    }
    EXPECT_TRUE(valid_frames(s->mueller, wo, s->wi));
  }
  EXPECT_FALSE(lobe.sample(direction(2.0f, 0.0f), 0.5f, {0.3f, 0.3f}, test_wavelengths()))
      << "below the surface";
  EXPECT_TRUE(lobe.eval(direction(0.3f, 0.0f), direction(0.3f, kPi), test_wavelengths()).is_black());
  EXPECT_EQ(lobe.pdf(direction(0.3f, 0.0f), direction(0.3f, kPi), test_wavelengths()), 0.0f);
  // Outside sample() a delta lobe's response is zero, with frames still perpendicular to the beams.
  const Vec3 wo = direction(0.3f, 0.0f), wi = direction(1.1f, 2.0f);
  const MuellerResponse r = lobe.eval_mueller(wo, wi, test_wavelengths());
  EXPECT_TRUE(valid_frames(r, wo, wi));
  EXPECT_EQ(r.m[0](0, 0), 0.0f);
}

TEST(SmoothConductor, SilverAt45DegreesInTheLobeFrames) {
  const SmoothConductorLobe lobe(kSilverN, kSilverK);
  const Vec3 wo = direction(kPi / 4, 1.1f);
  const auto s = lobe.sample(wo, 0.0f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(s);
  // The note's silver matrix, unchanged: the lobe frames are those of the note (x = s for both beams).
  EXPECT_NEAR(s->mueller.m[0](0, 1), 0.0107235f, 2e-6f);
  EXPECT_NEAR(s->mueller.m[0](2, 3), -0.3257540f, 2e-6f);
  EXPECT_NEAR(s->mueller.m[0](3, 2), 0.3257540f, 2e-6f);
  // in_x is the s direction: perpendicular to the plane of incidence (normal, wi, wo).
  EXPECT_NEAR(dot(s->mueller.in_x, Vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_NEAR(dot(s->mueller.in_x, s->wi), 0.0f, 1e-6f);
  EXPECT_NEAR(dot(s->mueller.out_x, wo), 0.0f, 1e-6f);
}

// Physical test (1): a perfect mirror at normal incidence keeps the world orientation of linear
// polarization and flips the handedness of circular polarization (the propagation reverses).
TEST(SmoothConductor, PerfectMirrorKeepsLinearOrientationAndFlipsHandedness) {
  const SmoothConductorLobe mirror(SampledSpectrum(0.0f), SampledSpectrum(1e4f));
  for (const Vec3& wo : {Vec3(0, 0, 1), normalize(Vec3(1e-4f, -2e-4f, 1.0f))}) {
    const auto s = mirror.sample(wo, 0.0f, {0, 0}, test_wavelengths());
    ASSERT_TRUE(s);
    const Mueller& m = s->mueller.m[0];
    EXPECT_NEAR(m(0, 0), 1.0f, 1e-3f);
    const Vec3 d_in = -s->wi, d_out = wo;
    for (float angle : {0.0f, 0.4f, 1.0f, 2.2f}) {
      const Vec3 e =
          normalize(cross(d_in, Vec3(std::cos(angle), std::sin(angle), 0.0f)));  // some perpendicular
      const Stokes out = m * linear_stokes(e, d_in, s->mueller.in_x);
      const Vec3 e_out = polarization_direction(out, d_out, s->mueller.out_x);
      EXPECT_NEAR(std::fabs(dot(e_out, e)), 1.0f, 1e-3f) << angle;
      EXPECT_NEAR(out.degree_of_polarization(), 1.0f, 1e-3f);
    }
    const Stokes circular = m * Stokes{{1, 0, 0, 1}};
    EXPECT_NEAR(circular[3] / circular[0], -1.0f, 1e-3f);
  }
}

TEST(SmoothConductor, ZeroKIsTheDielectricReflection) {
  const SmoothConductorLobe lobe(SampledSpectrum(1.5f), SampledSpectrum(0.0f));
  for (float c : {1e-7f, 0.3f, 0.7f, 1.0f}) {
    const Vec3 wo(std::sqrt(1 - c * c), 0.0f, c);
    const auto s = lobe.sample(wo, 0.0f, {0, 0}, test_wavelengths());
    ASSERT_TRUE(s);
    const Mueller want = specular_reflection(c, 1.5f);
    for (int r = 0; r < 4; ++r)
      for (int col = 0; col < 4; ++col) EXPECT_NEAR(s->mueller.m[2](r, col), want(r, col), 1e-6f);
  }
}

TEST(RoughConductor, MuellerM00EqualsEvalAndFramesAreValid) {
  const RoughConductorLobe lobe(lanes({0.2f, 0.5f, 1.2f, 0.14f}), lanes({3.0f, 2.5f, 7.0f, 4.0f}), 0.3f,
                                0.15f);
  Pcg32 rng(11);
  int nonzero = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 wo = direction(std::acos(rng.next_float()), 2 * kPi * rng.next_float());
    const Vec3 wi = direction(std::acos(rng.next_float()), 2 * kPi * rng.next_float());
    const SampledSpectrum f = lobe.eval(wo, wi, test_wavelengths());
    const MuellerResponse r = lobe.eval_mueller(wo, wi, test_wavelengths());
    for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(r.m[k](0, 0), f[k], 1e-6f * (1 + f[k]));
    EXPECT_TRUE(valid_frames(r, wo, wi));
    nonzero += f[0] > 0.0f;
  }
  EXPECT_EQ(nonzero, 2000);
}

TEST(RoughConductor, IsReciprocal) {
  const RoughConductorLobe lobe(kSilverN, kSilverK, 0.4f);
  Pcg32 rng(5);
  for (int i = 0; i < 500; ++i) {
    const Vec3 a = direction(std::acos(rng.next_float()), 2 * kPi * rng.next_float());
    const Vec3 b = direction(std::acos(rng.next_float()), 2 * kPi * rng.next_float());
    const float fab = lobe.eval(a, b, test_wavelengths())[0], fba = lobe.eval(b, a, test_wavelengths())[0];
    EXPECT_NEAR(fab, fba, 1e-5f * (1 + fab));
  }
}

TEST(RoughConductor, SampledMuellerIsTheFresnelMatrixAtTheMicrofacet) {
  const RoughConductorLobe lobe(kSilverN, kSilverK, 0.3f);
  Pcg32 rng(3);
  const Vec3 wo = direction(0.8f, 0.2f);
  for (int i = 0; i < 200; ++i) {
    const auto s = lobe.sample(wo, 0.0f, {rng.next_float(), rng.next_float()}, test_wavelengths());
    if (!s) continue;
    const Vec3 h = normalize(wo + s->wi);
    const Mueller fresnel = specular_reflection(dot(wo, h), std::complex<float>(0.136125f, -4.010625f));
    const float scale = s->weight[0] / fresnel(0, 0);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(s->mueller.m[0](r, c), fresnel(r, c) * scale, 1e-5f);
    EXPECT_NEAR(dot(s->mueller.in_x, h), 0.0f, 1e-5f) << "s axis of the microfacet";
    EXPECT_TRUE(valid_frames(s->mueller, wo, s->wi));
  }
}

TEST(RoughConductor, ChiSquareOfSampleAgainstPdf) {
  const SampledWavelengths& lambda = test_wavelengths();
  struct Case {
    float alpha_x, alpha_y, theta;
  };
  const Case cases[] = {{0.1f, 0.1f, 0.3f}, {0.3f, 0.3f, 0.0f},  {0.3f, 0.3f, 1.2f}, {0.6f, 0.6f, 0.8f},
                        {1.0f, 1.0f, 1.5f}, {0.3f, 0.3f, 1.55f}, {0.15f, 0.5f, 0.9f}};
  const double significance = sidak_significance(0.01, int(std::size(cases)));
  int seed = 100;
  for (const Case& c : cases) {
    const RoughConductorLobe lobe(kSilverN, kSilverK, c.alpha_x, c.alpha_y);
    const Chi2Result r = chi2_test(lobe, direction(c.theta, 0.4f), lambda, 40, 80, 300'000, seed++);
    SCOPED_TRACE(r.summary());
    std::printf("rough conductor alpha (%g, %g) theta %g: %s\n", c.alpha_x, c.alpha_y, c.theta,
                r.summary().c_str());
    EXPECT_GT(r.p_value, significance);
    EXPECT_EQ(r.weight_mismatches, 0);
    EXPECT_EQ(r.pdf_mismatches, 0);
    EXPECT_EQ(r.samples_in_empty_cells, 0);
  }
}

// White furnace: with reflectance 1 (k -> infinity) the directional albedo is the fraction of light the
// single-scattering microfacet model keeps; it must not exceed 1. The loss (multiple scattering between
// microfacets, not modelled) grows with roughness and towards grazing angles; the figures are printed.
TEST(RoughConductorFurnace, AlbedoIsAtMostOneAndTheLossIsReported) {
  const SampledSpectrum n(0.0f), k(1e6f);  // |r_s| = |r_p| = 1 to 1e-6
  Pcg32 rng(77);
  const int samples = 100'000;
  for (float alpha : {0.1f, 0.3f, 0.6f, 1.0f}) {
    const RoughConductorLobe lobe(n, k, alpha);
    std::printf("furnace alpha %.1f:", alpha);
    for (float theta_deg : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
      const Vec3 wo = direction(theta_deg * kPi / 180, 0.3f);
      double sum = 0.0;
      for (int i = 0; i < samples; ++i)
        if (const auto s = lobe.sample(wo, 0.0f, {rng.next_float(), rng.next_float()}, test_wavelengths()))
          sum += s->weight[0];
      const double albedo = sum / samples;
      std::printf("  %2.0f deg %.4f", theta_deg, albedo);
      EXPECT_LE(albedo, 1.0 + 1e-4) << alpha << " " << theta_deg;
      // At normal incidence only microfacets tilted less than 45 deg reflect above the horizon; their
      // projected area is tan^2(45) / (alpha^2 + tan^2(45)) = 1 / (1 + alpha^2) (GGX's slope CDF), an
      // upper bound of the albedo (G2 <= 1) that is nearly reached when alpha is small.
      if (theta_deg == 0.0f) {
        EXPECT_LE(albedo, 1.0 / (1.0 + alpha * alpha) + 2e-3) << alpha;
        EXPECT_GT(albedo, 0.6 / (1.0 + alpha * alpha)) << alpha;
      }
      if (alpha <= 0.1f && theta_deg <= 30.0f) {
        EXPECT_GT(albedo, 0.98);
      }
      EXPECT_GT(albedo, 0.25);
    }
    std::printf("\n");
  }
  // The mean weight and a quadrature of eval cos over the hemisphere agree (independent estimator).
  const RoughConductorLobe lobe(n, k, 0.6f);
  const Vec3 wo = direction(1.0f, 0.0f);
  double quad = 0.0;
  const int nt = 400, np = 400;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const float cos_t = (i + 0.5f) / nt, phi = 2 * kPi * (j + 0.5f) / np;
      const float sin_t = std::sqrt(1 - cos_t * cos_t);
      const Vec3 wi(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
      quad += lobe.eval(wo, wi, test_wavelengths())[0] * cos_t * (2 * kPi / (double(nt) * np));
    }
  double sum = 0.0;
  for (int i = 0; i < samples; ++i)
    if (const auto s = lobe.sample(wo, 0.0f, {rng.next_float(), rng.next_float()}, test_wavelengths()))
      sum += s->weight[0];
  std::printf("furnace alpha 0.6, theta 57.3 deg: quadrature %.4f, sampling %.4f\n", quad, sum / samples);
  EXPECT_NEAR(quad, sum / samples, 0.005);
}

TEST(RoughConductor, HardCasesGiveNoNaN) {
  for (float alpha : {1e-4f, 1e-3f, 1.0f}) {
    const RoughConductorLobe lobe(kSilverN, kSilverK, alpha);
    Pcg32 rng(9);
    for (float c : {1.0f, 0.5f, 1e-3f, 1e-7f}) {
      const Vec3 wo(std::sqrt(1 - c * c), 0.0f, c);
      for (int i = 0; i < 1000; ++i) {
        const auto s = lobe.sample(wo, 0.0f, {rng.next_float(), rng.next_float()}, test_wavelengths());
        if (!s) continue;
        EXPECT_TRUE(all_finite(s->weight)) << alpha << " " << c;
        EXPECT_TRUE(all_finite(s->mueller.m[0]));
        EXPECT_TRUE(std::isfinite(s->pdf) && s->pdf > 0.0f);
        EXPECT_LE(s->weight[0], 1.0f + 1e-4f);
      }
      const Vec3 mirror(-wo.x, -wo.y, wo.z);
      EXPECT_TRUE(all_finite(lobe.eval(wo, mirror, test_wavelengths())));
      EXPECT_TRUE(std::isfinite(lobe.pdf(wo, mirror, test_wavelengths())));
      EXPECT_TRUE(all_finite(lobe.eval_mueller(wo, mirror, test_wavelengths()).m[0]));
      EXPECT_TRUE(all_finite(lobe.eval(wo, Vec3(0, 0, 1), test_wavelengths())));
    }
  }
}

TEST(RoughConductor, TinyRoughnessApproachesTheMirror) {
  const RoughConductorLobe rough(kSilverN, kSilverK, 1e-3f);
  const SmoothConductorLobe smooth(kSilverN, kSilverK);
  const Vec3 wo = direction(0.7f, 0.0f);
  const auto a = rough.sample(wo, 0.0f, {0.37f, 0.61f}, test_wavelengths());
  const auto b = smooth.sample(wo, 0.0f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(a && b);
  EXPECT_GT(dot(a->wi, b->wi), 0.9999f);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a->mueller.m[0](r, c), b->mueller.m[0](r, c), 2e-3f);
}

// ---------------------------------------------------------------- the closure node

class ConductorNode : public ::testing::Test {
 protected:
  const Closure& evaluate(const std::string& json) {
    material = compile(json);
    ctx.lambda = &test_wavelengths();
    arena.reset();
    closure = Closure();
    material->evaluate(ctx, arena, closure);
    return closure;
  }
  ShadingContext ctx;
  LobeArena arena;
  Closure closure;
  std::shared_ptr<const CompiledMaterial> material;
};

TEST_F(ConductorNode, NamedGoldMirror) {
  const Closure& c = evaluate(R"({"type": "conductor", "metal": "Au"})");
  ASSERT_EQ(c.lobe_count(), 1);
  EXPECT_TRUE(material->facts().polarizes);
  EXPECT_TRUE(material->facts().has_delta_lobes);
  EXPECT_TRUE(material->facts().spectrally_varying);
  EXPECT_TRUE(c.polarizes());
  const auto s = c.lobe(0).lobe->sample(Vec3(0, 0, 1), 0.0f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(s);
  const SampledWavelengths& l = test_wavelengths();
  const SampledSpectrum n = named_spectrum("metal-Au-eta")->sample(l),
                        k = named_spectrum("metal-Au-k")->sample(l);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float want = ((n[i] - 1) * (n[i] - 1) + k[i] * k[i]) / ((n[i] + 1) * (n[i] + 1) + k[i] * k[i]);
    EXPECT_NEAR(s->weight[i], want, 1e-5f) << l[i];
  }
  EXPECT_GT(s->weight[3], s->weight[0]) << "gold reflects 700 nm better than 400 nm";
}

TEST_F(ConductorNode, RoughWithExplicitIndexAndDefaults) {
  const Closure& c = evaluate(R"({"type": "conductor", "eta": 0.2, "k": 3.0, "roughness": 0.3})");
  ASSERT_EQ(c.lobe_count(), 1);
  EXPECT_FALSE(material->facts().has_delta_lobes);
  EXPECT_TRUE(material->facts().polarizes);
  const Vec3 wo = direction(0.5f, 0.0f), wi = direction(0.5f, kPi);
  const RoughConductorLobe want(SampledSpectrum(0.2f), SampledSpectrum(3.0f), 0.3f);
  EXPECT_FLOAT_EQ(c.lobe(0).lobe->eval(wo, wi, test_wavelengths())[1],
                  want.eval(wo, wi, test_wavelengths())[1]);
  // Defaults: copper.
  const Closure& cu = evaluate(R"({"type": "conductor"})");
  ASSERT_EQ(cu.lobe_count(), 1);
  const auto s = cu.lobe(0).lobe->sample(Vec3(0, 0, 1), 0.0f, {0, 0}, test_wavelengths());
  ASSERT_TRUE(s);
  const float n = named_spectrum("metal-Cu-eta")->eval(600.0f),
              k = named_spectrum("metal-Cu-k")->eval(600.0f);
  EXPECT_NEAR(s->weight[2], fresnel_conductor(1.0f, n, k), 1e-6f);
}

TEST_F(ConductorNode, RejectsUnknownMetalsAndBadRoughness) {
  EXPECT_THROW(compile(R"({"type": "conductor", "metal": "Pt"})"), GraphError);
  EXPECT_THROW(compile(R"({"type": "conductor", "roughness": -0.1})"), GraphError);
  EXPECT_THROW(compile(R"({"type": "conductor", "k": -1})"), GraphError);
}

}  // namespace
}  // namespace ochre::test::conductor_test
