#include "renderer/environment_light.h"

#include <cmath>

#include "materials/sampling.h"
#include "spectra/cie.h"

namespace ochre {

EnvironmentLight::EnvironmentLight(SpectrumPtr radiance, float scene_radius)
    : radiance_(std::move(radiance)), scene_radius_(scene_radius) {}

std::optional<LightSample> EnvironmentLight::sample(const Vec3&, const Vec2& u,
                                                    const SampledWavelengths& lambda) const {
  LightSample s;
  s.wi = sample_uniform_sphere(u);
  s.distance = INFINITY;
  s.radiance = radiance_->sample(lambda);
  s.pdf = kUniformSpherePdf;
  return s;
}

float EnvironmentLight::power() const {
  // Flux of a uniform radiance field through the scene's bounding sphere (pbrt's estimate).
  return 4.0f * kPi * kPi * scene_radius_ * scene_radius_ * spectrum_to_xyz(*radiance_).y;
}

SampledSpectrum EnvironmentLight::radiance(const Vec3&, const SampledWavelengths& lambda) const {
  return radiance_->sample(lambda);
}

float EnvironmentLight::pdf(const Vec3&) const {
  return kUniformSpherePdf;
}

}  // namespace ochre
