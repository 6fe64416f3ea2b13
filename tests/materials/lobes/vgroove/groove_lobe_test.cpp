// The groove lobes: the explicit microgroove lobe reproduces the analytic V-groove lobe ray for ray on a
// V profile; every profile conserves energy with ideal mirrors; sampling the lobe estimates the exact
// R(theta, phi); the groove axis turns the response with the surface.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/microgroove_lobe.h"
#include "materials/lobes/vgroove/vgroove_lobe.h"
#include "materials/lobes/vgroove/vgroove_reference.h"

namespace ochre::test::groove_lobe_test {
namespace {

FacetSpectrum silicon() {
  FacetSpectrum f;
  f.n = SampledSpectrum(4.073f);
  f.k = SampledSpectrum(0.028f);
  return f;
}

FacetSpectrum mirror() {
  FacetSpectrum f;
  f.mirror = true;
  return f;
}

const SampledWavelengths& wavelengths() {
  static const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.3f);
  return lambda;
}

Vec3 direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float cos_theta = 0.02f + 0.98f * u(rng), phi = 2.0f * std::numbers::pi_v<float> * u(rng);
  const float sin_theta = std::sqrt(1.0f - cos_theta * cos_theta);
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

TEST(GrooveLobes, MicrogrooveOnAVProfileReproducesVGrooveRayForRay) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (double alpha_deg : {5.0, 30.0, 45.0, 90.0, 150.0}) {
    for (ChainModel model : {ChainModel::kRigorous, ChainModel::kSeparateSP, ChainModel::kUnpolarized}) {
      const Vec3 axis{0.6f, 0.8f, 0.0f};
      const GrooveProfile profile = GrooveProfile::v(alpha_deg * kDegD);
      const VGrooveLobe analytic(alpha_deg * kDegD, axis, silicon(), model, 0);
      const MicrogrooveLobe explicit_lobe({&profile}, axis, silicon(), model, 0);
      int compared = 0, differing_paths = 0;
      for (int i = 0; i < 4000; ++i) {
        const Vec3 wo = direction(rng);
        const Vec2 uu{u(rng), u(rng)};
        const auto a = analytic.sample(wo, 0.5f, uu, wavelengths());
        const auto b = explicit_lobe.sample(wo, 0.5f, uu, wavelengths());
        ASSERT_TRUE(a && b);
        if (!(a->wi == b->wi)) {  // a ray within rounding of a breakpoint: a different path
          ++differing_paths;
          continue;
        }
        ++compared;
        for (int k = 0; k < kSpectrumSamples; ++k) {
          ASSERT_EQ(a->weight[k], b->weight[k]);
          if (a->has_mueller) {
            for (int r = 0; r < 4; ++r)
              for (int c = 0; c < 4; ++c) ASSERT_EQ(a->mueller.m[k](r, c), b->mueller.m[k](r, c));
          }
        }
        ASSERT_EQ(a->mueller.in_x, b->mueller.in_x);
        ASSERT_EQ(a->mueller.out_x, b->mueller.out_x);
      }
      EXPECT_LE(differing_paths, 2) << alpha_deg;
      EXPECT_GE(compared, 3990);
    }
  }
}

TEST(GrooveLobes, EveryProfileConservesEnergyWithIdealMirrors) {
  const GrooveProfile profiles[] = {
      GrooveProfile::v(20 * kDegD), GrooveProfile::asymmetric_v(30 * kDegD, 70 * kDegD),
      GrooveProfile::flat_bottom(60 * kDegD, 0.4), GrooveProfile::rounded(40 * kDegD, 48)};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (const GrooveProfile& profile : profiles) {
    for (ChainModel model : {ChainModel::kRigorous, ChainModel::kSeparateSP, ChainModel::kUnpolarized}) {
      const MicrogrooveLobe lobe({&profile}, {1, 0, 0}, mirror(), model, 0);
      for (int i = 0; i < 2000; ++i) {
        const auto s = lobe.sample(direction(rng), u(rng), {u(rng), u(rng)}, wavelengths());
        ASSERT_TRUE(s);
        ASSERT_GT(s->wi.z, 0.0f);
        for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_NEAR(s->weight[k], 1.0f, 1e-6f);
      }
    }
  }
  const MicrogrooveLobe mix({nullptr, 30 * kDegD, 120 * kDegD}, {1, 0, 0}, mirror(), ChainModel::kRigorous,
                            0);
  for (int i = 0; i < 2000; ++i) {
    const auto s = mix.sample(direction(rng), u(rng), {u(rng), u(rng)}, wavelengths());
    ASSERT_TRUE(s);
    ASSERT_NEAR(s->weight[0], 1.0f, 1e-6f);
  }
}

TEST(GrooveLobes, DegenerateProfilesEqualTheVGroove) {
  // A flat bottom of depth fraction 0, an asymmetric V with equal slopes and a mix of one angle are all
  // the symmetric V: the same mean reflectance (the asymmetric V is scaled, so paths match up to rounding).
  const double alpha = 50 * kDegD, slope = 0.5 * (std::numbers::pi - alpha);
  const GrooveProfile v = GrooveProfile::v(alpha), flat = GrooveProfile::flat_bottom(alpha, 0.0),
                      asym = GrooveProfile::asymmetric_v(slope, slope);
  const MicrogrooveLobe a({&v}, {1, 0, 0}, silicon(), ChainModel::kRigorous, 0);
  const MicrogrooveLobe b({&flat}, {1, 0, 0}, silicon(), ChainModel::kRigorous, 0);
  const MicrogrooveLobe c({&asym}, {1, 0, 0}, silicon(), ChainModel::kRigorous, 0);
  const MicrogrooveLobe d({nullptr, alpha, alpha}, {1, 0, 0}, silicon(), ChainModel::kRigorous, 0);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 3000; ++i) {
    const Vec3 wo = direction(rng);
    const Vec2 uu{u(rng), u(rng)};
    const float want = a.sample(wo, 0.5f, uu, wavelengths())->weight[0];
    EXPECT_NEAR(b.sample(wo, 0.5f, uu, wavelengths())->weight[0], want, 1e-6f);
    EXPECT_NEAR(d.sample(wo, 0.5f, uu, wavelengths())->weight[0], want, 1e-6f);
    const auto sc = c.sample(wo, 0.5f, uu, wavelengths());
    if (length(sc->wi - a.sample(wo, 0.5f, uu, wavelengths())->wi) < 1e-5f) {
      EXPECT_NEAR(sc->weight[0], want, 1e-5f);
    }
  }
}

TEST(GrooveLobes, SamplingTheVGrooveLobeEstimatesTheExactReflectance) {
  const Vec3 axis{std::cos(0.4f), std::sin(0.4f), 0.0f};
  const VGrooveLobe lobe(45 * kDegD, axis, silicon(), ChainModel::kRigorous, 0);
  const VGroove groove(45 * kDegD);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (double theta_deg : {20.0, 61.0, 80.0}) {
    for (double phi_deg : {0.0, 35.0, 90.0}) {
      // wo in the local frame: phi is measured from the groove frame's y axis (across the grooves).
      const Vec3d e = groove_direction(theta_deg * kDegD, phi_deg * kDegD);
      const Vec3 across{-axis.y, axis.x, 0.0f};
      const Vec3 wo = axis * float(e.x) + across * float(e.y) + Vec3(0, 0, float(e.z));
      const double exact =
          directional_reflectance(groove, e, ChainModel::kRigorous,
                                  std::vector<FacetIndex>{FacetIndex::conductor(4.073, 0.028)})
              .reflectance[0];
      const int n = 20000;
      double sum = 0, sum2 = 0;
      for (int i = 0; i < n; ++i) {
        const auto s = lobe.sample(wo, u(rng), {u(rng), u(rng)}, wavelengths());
        const double w = s ? s->weight[0] : 0.0;
        sum += w;
        sum2 += w * w;
      }
      const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
      EXPECT_NEAR(mean, exact, 3.0 * se + 2e-6) << theta_deg << " " << phi_deg;
    }
  }
}

TEST(GrooveLobes, ReflectionLimitAbsorbsLongerPaths) {
  const VGrooveLobe limited(30 * kDegD, {1, 0, 0}, mirror(), ChainModel::kRigorous, 2);
  const VGroove groove(30 * kDegD);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 wo = direction(rng);
    const Vec2 uu{u(rng), u(rng)};
    const VGroovePath path = groove.trace(normalize(Vec3d(wo)), (2.0 * uu.x - 1.0) * groove.half_opening());
    EXPECT_EQ(limited.sample(wo, 0.5f, uu, wavelengths()).has_value(), path.reflections <= 2);
  }
}

TEST(GrooveLobes, MuellerFramesArePerpendicularToTheirBeams) {
  const VGrooveLobe lobe(40 * kDegD, {0.28f, 0.96f, 0}, silicon(), ChainModel::kRigorous, 0);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 wo = direction(rng);
    const auto s = lobe.sample(wo, 0.5f, {u(rng), u(rng)}, wavelengths());
    ASSERT_TRUE(s && s->has_mueller);
    EXPECT_NEAR(dot(s->mueller.in_x, s->wi), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(s->mueller.out_x, wo), 0.0f, 1e-5f);
    EXPECT_NEAR(length(s->mueller.in_x), 1.0f, 1e-5f);
    // M00 is the weight; a passive chain never has |M_0j| > M00.
    for (int k = 0; k < kSpectrumSamples; ++k) {
      EXPECT_FLOAT_EQ(s->mueller.m[k](0, 0), s->weight[k]);
      const float m00 = s->mueller.m[k](0, 0);
      EXPECT_LE(std::hypot(s->mueller.m[k](0, 1), s->mueller.m[k](0, 2), s->mueller.m[k](0, 3)),
                m00 * (1 + 1e-5f));
    }
  }
}

}  // namespace
}  // namespace ochre::test::groove_lobe_test
