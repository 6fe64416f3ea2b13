// Light::importance and the per-point light choice built on it (Scene::light_pmfs): the estimates' closed
// forms, and probabilities that follow them a quarter, and the lights' power three quarters.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/lights/environment_light.h"
#include "renderer/lights/point_light.h"
#include "renderer/lights/sphere_light.h"
#include "renderer/lights/spot_light.h"
#include "renderer/scene/scene.h"
#include "spectra/cie.h"
#include "spectra/constant_spectrum.h"

namespace ochre::light_importance_test {
namespace {

SpectrumPtr constant(float v) {
  return std::make_shared<ConstantSpectrum>(v);
}

// Luminance of a constant spectrum of value v.
float luminance(float v) {
  return spectrum_to_xyz(ConstantSpectrum(v)).y;
}

TEST(LightImportance, EstimatesFollowTheInverseSquareLawAndTheSpotProfile) {
  const PointLight point({0, 0, 2}, constant(3.0f));
  EXPECT_NEAR(point.importance({0, 0, 0}), luminance(3.0f) / 4.0f, 1e-5f);
  EXPECT_NEAR(point.importance({3, 0, 6}), luminance(3.0f) / 25.0f, 1e-5f);

  const SphereLight sphere({0, 0, 0}, 0.5f, constant(2.0f));
  EXPECT_NEAR(sphere.importance({0, 2, 0}), luminance(2.0f) / 4.0f, 1e-5f);
  EXPECT_NEAR(sphere.importance({0, 0.1f, 0}), luminance(2.0f) / 0.25f,
              1e-4f);  // inside: never nearer than r

  const SpotLight spot({0, 0, 0}, {0, 0, -1}, 30.0f, 20.0f, constant(1.0f), SpotLight::Falloff::Linear);
  EXPECT_NEAR(spot.importance({0, 0, -2}), luminance(1.0f) / 4.0f, 1e-5f);
  EXPECT_EQ(spot.importance({0, 2, -2}), 0.0f);  // 45 degrees off the axis: outside the cone
  EXPECT_EQ(spot.importance({0, 0, 2}), 0.0f);   // behind

  const EnvironmentLight sky(constant(0.25f), 100.0f, 2.0f);
  EXPECT_NEAR(sky.importance({5, 5, 5}), M_PI * luminance(0.25f) * 2.0f, 1e-4f);
}

TEST(LightImportance, PerPointProbabilitiesMixTheEstimatesWithThePower) {
  Scene scene;
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 0, 1), constant(1.0f)));
  scene.lights.push_back(std::make_unique<PointLight>(Vec3(10, 0, 1), constant(1.0f)));
  scene.lights.push_back(std::make_unique<SpotLight>(Vec3(0, 0, 5), Vec3(0, 0, -1), 10.0f, 5.0f,
                                                     constant(1.0f), SpotLight::Falloff::Linear));
  scene.update_light_selection();
  ASSERT_TRUE(scene.local_light_selection(LightSelection::kLocal));
  // By power: the two point lights 4 pi each, the narrow spot 2 pi (1 - cos) and a bit.
  EXPECT_NEAR(scene.light_pmf(0), scene.light_pmf(1), 1e-7);
  EXPECT_LT(scene.light_pmf(2), 0.02f);
  Scene::LightPmfs pmf{};
  scene.light_pmfs({0, 0, 0}, pmf);
  // Importances 1, 1/101, 1/25 (times the same luminance).
  const double total = 1.0 + 1.0 / 101.0 + 1.0 / 25.0;
  EXPECT_NEAR(pmf[0], 0.25 * 1.0 / total + 0.75 * scene.light_pmf(0), 1e-6);
  EXPECT_NEAR(pmf[1], 0.25 * (1.0 / 101.0) / total + 0.75 * scene.light_pmf(1), 1e-6);
  EXPECT_NEAR(pmf[2], 0.25 * (1.0 / 25.0) / total + 0.75 * scene.light_pmf(2), 1e-6);
  // Next to the second light it takes the lead; outside the spot's cone the spot keeps its power share.
  scene.light_pmfs({10, 0, 0}, pmf);
  EXPECT_GT(pmf[1], pmf[0] + 0.2f);
  EXPECT_NEAR(pmf[2], 0.75 * scene.light_pmf(2), 1e-6);
  EXPECT_NEAR(pmf[0] + pmf[1] + pmf[2], 1.0, 1e-6);

  // By power only on request, and for one light or more than kMaxLocalLights.
  EXPECT_FALSE(scene.local_light_selection(LightSelection::kPower));
  while (scene.lights.size() <= Scene::kMaxLocalLights)
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 0, 1), constant(1.0f)));
  EXPECT_FALSE(scene.local_light_selection(LightSelection::kLocal));
  scene.lights.resize(1);
  EXPECT_FALSE(scene.local_light_selection(LightSelection::kLocal));
}

}  // namespace
}  // namespace ochre::light_importance_test
