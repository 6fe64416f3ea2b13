#pragma once
// Directional light: parallel light from infinitely far away along one direction (the sun seen from the
// ground, Mitsuba 3's "directional" emitter, Blender's sun lamp without its angular size). A surface facing
// it receives the irradiance E(lambda) (W m^-2 nm^-1 in relative units) times the cosine of the angle to
// the direction. Camera and BSDF rays cannot hit it (a delta in direction): next-event estimation alone
// finds it.

#include "renderer/lights/light.h"
#include "spectra/memoized_spectrum.h"

namespace ochre {

class DirectionalLight final : public Light {
 public:
  // `direction`: where the light travels (from the light toward the scene); need not be unit length.
  // `scene_radius`: the radius of the scene's bounding sphere, for the power estimate.
  DirectionalLight(const Vec3& direction, SpectrumPtr irradiance, float scene_radius);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  // The flux through the scene's cross-section: pi r^2 E.
  float power() const override;
  float importance(const Vec3& p) const override;
  bool is_delta() const override { return true; }
  const Spectrum* emission_spectrum() const override { return irradiance_.spectrum().get(); }

 private:
  Vec3 to_light_;  // unit, opposite to the direction of travel
  MemoizedSpectrum irradiance_;
  float luminance_;  // of the irradiance
  float scene_radius_;
};

}  // namespace ochre
