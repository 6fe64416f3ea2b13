#pragma once
// Light: an emitter that next-event estimation can sample. Implementations:
// point_light.h, spot_light.h, sphere_light.h, environment_light.h, area_light.h.

#include <optional>
#include <string>

#include "materials/core/vec3.h"
#include "spectra/sampled_wavelengths.h"
#include "spectra/spectrum.h"

namespace ochre {

struct LightSample {
  Vec3 wi;                   // unit direction from the reference point toward the light
  float distance = 0.0f;     // to the sampled point (INFINITY for the environment)
  SampledSpectrum radiance;  // arriving radiance (point lights: intensity / distance^2)
  float pdf = 0.0f;          // solid-angle pdf (delta lights: 1)
  bool delta = false;
  // A light that camera and BSDF rays cannot hit (sphere_light.h): light sampling is its only strategy,
  // so its samples take no MIS weight.
  bool only_by_light_sampling = false;
  Vec3 light_normal;  // geometric normal at the sampled point (area lights)
};

// The light group of the emitters that name none (docs/lights.md, "Light groups"): a reserved name.
inline constexpr const char* kOtherLightGroup = "other";

class Light {
 public:
  virtual ~Light() = default;
  // Samples a point on the light as seen from `ref` (world space).
  virtual std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                            const SampledWavelengths& lambda) const = 0;
  // Flux estimate (W-like, luminance-weighted) used to choose among lights.
  virtual float power() const = 0;
  // Estimate of the illuminance (luminance-weighted irradiance) the light can give at p, ignoring
  // visibility and the receiver's orientation: never 0 where the light can reach p (only outside a spot's
  // cone). Chooses among a scene's few lights at each shading point (scene.h, light_pmfs).
  virtual float importance(const Vec3& p) const = 0;
  virtual bool is_delta() const { return false; }
  // The spectrum the light emits, up to a factor that does not depend on the wavelength, when it has one
  // (a map or a textured surface has none: null). `ochre relight` changes it (docs/lights.md, "Relighting").
  virtual const Spectrum* emission_spectrum() const { return nullptr; }

  // Transmission axis (world) of a linear polarizer in front of the light (light_polarizer.h), if any.
  std::optional<Vec3> polarizer_axis;
  // The light group the light belongs to ("group" of a light, "light_group" of an emissive shape; docs/
  // lights.md, "Light groups"); empty: none.
  std::string group;
};

}  // namespace ochre
