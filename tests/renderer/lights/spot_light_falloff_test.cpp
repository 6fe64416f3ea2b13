// The spot light's two falloff ramps (renderer/lights/spot_light.h): pbrt-v4's smoothstep in the cosine and
// Mitsuba 3's linear ramp in the angle, and a power (used to choose lights) that is the integral of the
// profile over the sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/lights/spot_light.h"
#include "spectra/constant_spectrum.h"

namespace ochre::spot_light_falloff_test {
namespace {

Vec3 at_angle(double degrees) {
  const double a = degrees * M_PI / 180.0;
  return {static_cast<float>(std::sin(a)), 0.0f, static_cast<float>(std::cos(a))};
}

SpotLight spot(SpotLight::Falloff falloff) {
  return SpotLight({0, 0, 0}, {0, 0, 1}, 30.0f, 20.0f, std::make_shared<ConstantSpectrum>(1.0f), falloff);
}

TEST(SpotLightFalloff, LinearRampIsLinearInTheAngle) {
  const SpotLight light = spot(SpotLight::Falloff::Linear);
  EXPECT_EQ(light.profile(at_angle(10)), 1.0f);
  EXPECT_NEAR(light.profile(at_angle(22.5)), 0.75, 1e-5);
  EXPECT_NEAR(light.profile(at_angle(25)), 0.5, 1e-5);
  EXPECT_NEAR(light.profile(at_angle(29)), 0.1, 1e-4);
  EXPECT_EQ(light.profile(at_angle(31)), 0.0f);
  // The smoothstep in the cosine is another curve through the same ends.
  EXPECT_GT(std::abs(spot(SpotLight::Falloff::Smoothstep).profile(at_angle(22.5)) - 0.75f), 0.01f);
}

TEST(SpotLightFalloff, PowerIsTheProfileIntegratedOverTheSphere) {
  for (const auto falloff : {SpotLight::Falloff::Linear, SpotLight::Falloff::Smoothstep}) {
    const SpotLight light = spot(falloff);
    double solid_angle = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {  // 2 pi sin(theta) d(theta) over [0, 40] degrees
      const double theta = (i + 0.5) / n * 40.0;
      solid_angle +=
          2 * M_PI * std::sin(theta * M_PI / 180) * (40.0 / n * M_PI / 180) * light.profile(at_angle(theta));
    }
    EXPECT_NEAR(light.power() / solid_angle, 1.0, 1e-4);  // a constant intensity 1 has luminance 1
  }
}

}  // namespace
}  // namespace ochre::spot_light_falloff_test
