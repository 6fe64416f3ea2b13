#pragma once
// Sphere light: a uniformly emitting sphere (a flame's bright volume seen from outside) of radius r
// whose radiant intensity I(lambda), seen from any direction, is that of a point light: its radiance
// is I / (pi r^2). It gives soft shadows where a point light gives hard ones. It is not geometry:
// camera and BSDF rays never hit it, so next-event estimation is the only strategy that finds it and
// needs no MIS weight (LightSample::only_by_light_sampling).
//
// Sampling (pbrt-v3, Sphere::Sample(ref, u)): a direction uniform in the cone the sphere subtends at
// the reference point, pdf 1 / (2 pi (1 - cos theta_max)). A point inside the sphere (a wall the flame
// touches) sees it as a point light at the centre whose distance is at least r, so the irradiance
// there is bounded by I / r^2.

#include "renderer/lights/light.h"
#include "spectra/memoized_spectrum.h"

namespace ochre {

class SphereLight final : public Light {
 public:
  SphereLight(const Vec3& center, float radius, SpectrumPtr intensity);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override;
  float importance(const Vec3& p) const override;
  const Spectrum* emission_spectrum() const override { return intensity_.spectrum().get(); }

  // A flickering flame moves and changes its intensity between frames (renderer/flame_flicker.h).
  void set_state(const Vec3& center, SpectrumPtr intensity);
  const Vec3& center() const { return center_; }
  float radius() const { return radius_; }
  const SpectrumPtr& intensity() const { return intensity_.spectrum(); }

 private:
  Vec3 center_;
  float radius_;
  MemoizedSpectrum intensity_;
  float luminance_;  // of the intensity
};

}  // namespace ochre
