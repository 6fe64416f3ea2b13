// Closure sampling: a closure of one lobe takes the lobe's own sample (no selection, no second evaluation),
// and that must be the same estimator as the general mixture path: the same direction and pdf, and a
// weight equal to eval |cos| / pdf, for a diffuse lobe, a rough (glossy, polarizing) lobe and a delta lobe.

#include "materials/lobes/closure.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/lobes/conductor.h"
#include "materials/lobes/lambert.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "materials/material_test_support.h"
#include "support/spectrum_lanes.h"

namespace ochre::test::closure_test {
namespace {

const SampledSpectrum kWeight = lanes({0.25f, 0.5f, 0.75f, 1.0f});

void expect_one_lobe_sample_is_the_mixture_estimator(const Lobe& lobe, const Vec3& wo) {
  Closure closure;
  closure.add_lobe(&lobe, kWeight);
  const SampledWavelengths& lambda = test_wavelengths();
  int sampled = 0;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const Vec2 u{(i + 0.5f) / 16, (j + 0.5f) / 16};
      const auto own = lobe.sample(wo, 0.3f, u, lambda);
      const auto s = closure.sample(wo, 0.3f, u, lambda);
      ASSERT_EQ(own.has_value(), s.has_value());
      if (!s) continue;
      ++sampled;
      EXPECT_EQ(s->wi.x, own->wi.x);
      EXPECT_EQ(s->wi.y, own->wi.y);
      EXPECT_EQ(s->wi.z, own->wi.z);
      EXPECT_EQ(s->pdf, own->pdf);
      EXPECT_EQ(s->delta, own->delta);
      for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_EQ(s->weight[k], own->weight[k] * kWeight[k]);
      if (s->delta) {
        EXPECT_EQ(closure.pdf(wo, s->wi, lambda), 0.0f) << "delta lobes have no density";
        continue;
      }
      EXPECT_FALSE(s->has_mueller) << "a non-delta sample's Mueller response comes from eval_mueller()";
      // The general path's weight: the closure's value and pdf in the sampled direction.
      const float pdf = closure.pdf(wo, s->wi, lambda);
      EXPECT_NEAR(pdf, s->pdf, 1e-5f * s->pdf);
      const SampledSpectrum mixture = closure.eval(wo, s->wi, lambda) * (std::fabs(s->wi.z) / pdf);
      for (int k = 0; k < kSpectrumSamples; ++k)
        EXPECT_NEAR(s->weight[k], mixture[k], 2e-5f * std::max(1.0f, mixture[k])) << "lane " << k;
    }
  EXPECT_GT(sampled, 100);
}

TEST(Closure, OneLambertLobeSamplesAsTheMixture) {
  const LambertLobe lambert;
  expect_one_lobe_sample_is_the_mixture_estimator(lambert, normalize(Vec3(0.3f, -0.2f, 0.9f)));
}

TEST(Closure, OneRoughConductorLobeSamplesAsTheMixture) {
  const RoughConductorLobe gold(SampledSpectrum(0.2f), SampledSpectrum(3.0f), 0.4f);
  expect_one_lobe_sample_is_the_mixture_estimator(gold, normalize(Vec3(0.5f, 0.1f, 0.6f)));
}

TEST(Closure, OneDeltaLobeKeepsItsMuellerMatrixTimesTheWeight) {
  const SmoothConductorLobe silver(SampledSpectrum(0.15f), SampledSpectrum(3.6f));
  const Vec3 wo = normalize(Vec3(0.4f, 0.2f, 0.7f));
  expect_one_lobe_sample_is_the_mixture_estimator(silver, wo);
  Closure closure;
  closure.add_lobe(&silver, kWeight);
  const auto own = silver.sample(wo, 0.5f, {0.5f, 0.5f}, test_wavelengths());
  const auto s = closure.sample(wo, 0.5f, {0.5f, 0.5f}, test_wavelengths());
  ASSERT_TRUE(own && s && own->has_mueller && s->has_mueller);
  for (int k = 0; k < kSpectrumSamples; ++k)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(s->mueller.m[k](r, c), own->mueller.m[k](r, c) * kWeight[k]);
}

TEST(Closure, OneLobePdfIsTheLobePdf) {
  const LambertLobe lambert;
  Closure closure;
  closure.add_lobe(&lambert, kWeight);
  const Vec3 wo = normalize(Vec3(0.1f, 0.2f, 0.9f)), wi = normalize(Vec3(-0.4f, 0.3f, 0.5f));
  EXPECT_EQ(closure.pdf(wo, wi, test_wavelengths()), lambert.pdf(wo, wi, test_wavelengths()));
  EXPECT_EQ(closure.pdf(wo, Vec3(0, 0, -1), test_wavelengths()), 0.0f);
}

// Copies carry only the lobes in use and clear() keeps the old slots: what a copy or a cleared closure
// reports must not depend on what the target held before.
TEST(Closure, CopiesAndClearDoNotKeepTheTargetsOldLobes) {
  const LambertLobe lambert;
  const SmoothConductorLobe silver(SampledSpectrum(0.15f), SampledSpectrum(3.6f));
  Closure big;
  for (int i = 0; i < 3; ++i)
    big.add_lobe(i == 1 ? static_cast<const Lobe*>(&silver) : &lambert, kWeight * (i + 1.0f));
  big.add_emission(SampledSpectrum(2.0f));
  big.set_tangent(Vec3(1, 0, 0));

  Closure one;
  one.add_lobe(&lambert, kWeight);
  Closure target = big;  // copy construction: everything of big
  ASSERT_EQ(target.lobe_count(), 3);
  EXPECT_EQ(target.lobe(1).lobe, &silver);
  EXPECT_EQ(target.lobe(2).weight[0], kWeight[0] * 3.0f);
  EXPECT_EQ(target.emission()[0], 2.0f);
  EXPECT_TRUE(target.has_tangent());
  EXPECT_TRUE(target.has_transmission() == big.has_transmission() && target.polarizes());

  target = one;  // fewer lobes over more: the silver lobe must be gone
  ASSERT_EQ(target.lobe_count(), 1);
  EXPECT_EQ(target.lobe(0).lobe, &lambert);
  EXPECT_FALSE(target.polarizes());
  EXPECT_FALSE(target.has_tangent());
  EXPECT_TRUE(target.emission().is_black());
  const Vec3 wo = normalize(Vec3(0.3f, 0.1f, 0.8f)), wi = normalize(Vec3(-0.2f, 0.4f, 0.7f));
  const SampledSpectrum want = one.eval(wo, wi, test_wavelengths());
  const SampledSpectrum got = target.eval(wo, wi, test_wavelengths());
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_EQ(got[k], want[k]);

  EXPECT_THROW((void)target.lobe(1), std::out_of_range) << "slot 1 still holds big's silver lobe";
  EXPECT_THROW((void)target.lobe(-1), std::out_of_range);
  target = big;
  target.clear();
  EXPECT_EQ(target.lobe_count(), 0);
  EXPECT_FALSE(target.has_lobes());
  EXPECT_FALSE(target.has_non_delta_lobes());
  EXPECT_FALSE(target.has_tangent());
  EXPECT_TRUE(target.emission().is_black());
  target.add_lobe(&silver, kWeight);  // refilled after clear(): only the new lobe counts
  EXPECT_EQ(target.lobe_count(), 1);
  EXPECT_FALSE(target.has_non_delta_lobes());
}

// A Lambert lobe whose albedo hint, a constant, counts its calls.
class CountingLambert final : public Lobe {
 public:
  explicit CountingLambert(float albedo) : albedo_(albedo) {}
  uint32_t flags() const override { return lambert_.flags(); }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& l) const override {
    return lambert_.eval(wo, wi, l);
  }
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& l) const override {
    return lambert_.pdf(wo, wi, l);
  }
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& l) const override {
    return lambert_.sample(wo, u_choice, u, l);
  }
  SampledSpectrum albedo_hint(const Vec3&, const SampledWavelengths&) const override {
    ++calls;
    return SampledSpectrum(albedo_);
  }
  mutable int calls = 0;

 private:
  LambertLobe lambert_;
  float albedo_;
};

// A vertex asks for the lobe selection weights two or three times with one wo: the lobes' albedo hints are
// computed once per wo, again for another wo, and again whenever the lobes or their weights change.
TEST(Closure, SelectionWeightsComputedOncePerOutgoingDirection) {
  const CountingLambert a(0.2f), b(0.8f), c(0.5f);
  const SampledWavelengths& lambda = test_wavelengths();
  const Vec3 wo = normalize(Vec3(0.3f, -0.2f, 0.9f)), other = normalize(Vec3(-0.1f, 0.4f, 0.8f));
  const Vec3 wi = normalize(Vec3(0.1f, 0.1f, 0.9f));
  Closure closure;
  closure.add_lobe(&a, SampledSpectrum(1.0f));
  closure.add_lobe(&b, SampledSpectrum(1.0f));
  const float pdf = closure.pdf(wo, wi, lambda);
  closure.sample(wo, 0.7f, Vec2{0.3f, 0.6f}, lambda);
  EXPECT_EQ(closure.pdf(wo, wi, lambda), pdf);
  EXPECT_EQ(a.calls, 1);
  EXPECT_EQ(b.calls, 1);
  closure.pdf(other, wi, lambda);
  EXPECT_EQ(a.calls, 2);
  // A third lobe changes the selection: its hint is asked for, and the others' again.
  closure.add_lobe(&c, SampledSpectrum(1.0f));
  closure.pdf(other, wi, lambda);
  EXPECT_EQ(a.calls, 3);
  EXPECT_EQ(c.calls, 1);
  closure.scale(SampledSpectrum(0.5f));
  closure.pdf(other, wi, lambda);
  EXPECT_EQ(a.calls, 4);
  // A copy starts afresh; the selection it computes is the original's.
  Closure copy;
  copy = closure;
  EXPECT_EQ(copy.pdf(other, wi, lambda), closure.pdf(other, wi, lambda));
  EXPECT_EQ(a.calls, 5);
  closure.clear();
  closure.add_lobe(&b, SampledSpectrum(1.0f));
  EXPECT_EQ(closure.pdf(other, wi, lambda), b.pdf(other, wi, lambda));
}

// A lobe that keeps its value and pdf for its sample (the Lambert-sphere lobe) lends them to the mixture: the
// mixture sample's pdf and weight are still exactly the whole closure's pdf() and eval() |cos| / pdf().
TEST(Closure, MixtureSampleReusesTheSampledLobesValueExactly) {
  const LambertSphereLobe sphere(LambertSphereVariant::kFull, lanes({0.3f, 0.6f, 0.9f, 0.95f}));
  const LambertLobe lambert;
  Closure closure;
  closure.add_lobe(&sphere, kWeight);
  closure.add_lobe(&lambert, SampledSpectrum(0.5f));
  const SampledWavelengths& lambda = test_wavelengths();
  const Vec3 wo = normalize(Vec3(0.3f, -0.2f, 0.9f));
  int reused = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const Vec2 u{(i + 0.5f) / 8, (j + 0.5f) / 8};
      const float u_choice = (i * 8 + j + 0.5f) / 64;
      const auto s = closure.sample(wo, u_choice, u, lambda);
      if (!s) continue;
      reused += sphere.sample(wo, 0.0f, u, lambda)->has_value;
      EXPECT_EQ(s->pdf, closure.pdf(wo, s->wi, lambda));
      const SampledSpectrum expected = closure.eval(wo, s->wi, lambda) * (std::fabs(s->wi.z) / s->pdf);
      for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_EQ(s->weight[k], expected[k]) << i << " " << j;
    }
  EXPECT_GT(reused, 0);
}

}  // namespace
}  // namespace ochre::test::closure_test
