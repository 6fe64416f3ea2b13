#pragma once
// Spot light: a point light whose intensity I(lambda) is confined to a cone. Full intensity inside
// `falloff_start` (half-angle), a ramp down to zero at `cone_angle` (half-angle), nothing outside. The
// ramp is a smoothstep in the cosine (pbrt-v4's spotlight profile) or linear in the angle (Mitsuba 3's
// spot emitter).

#include "renderer/lights/light.h"
#include "spectra/memoized_spectrum.h"

namespace ochre {

class SpotLight final : public Light {
 public:
  enum class Falloff { Smoothstep, Linear };

  // Angles are half-angles in degrees, 0 < falloff_start <= cone_angle <= 180.
  SpotLight(const Vec3& position, const Vec3& direction, float cone_angle_deg, float falloff_start_deg,
            SpectrumPtr intensity, Falloff falloff = Falloff::Smoothstep);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override;
  float importance(const Vec3& p) const override;
  bool is_delta() const override { return true; }
  const Spectrum* emission_spectrum() const override { return intensity_.spectrum().get(); }

  // Angular profile in [0, 1] for a direction leaving the light.
  float profile(const Vec3& direction) const;

 private:
  Vec3 position_, direction_;
  float cos_cone_, cos_falloff_;
  float cone_, falloff_start_;  // radians
  Falloff falloff_;
  MemoizedSpectrum intensity_;
  float luminance_;  // of the intensity on the axis
};

}  // namespace ochre
