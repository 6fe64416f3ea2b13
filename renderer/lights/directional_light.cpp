// The "directional" light type (docs/scene-format.md, "lights"; docs/lights.md).
#include "renderer/lights/directional_light.h"

#include <cmath>

#include "materials/core/pi.h"
#include "renderer/json/spectrum_json.h"
#include "renderer/lights/light_type.h"
#include "spectra/cie.h"

namespace ochre {

DirectionalLight::DirectionalLight(const Vec3& direction, SpectrumPtr irradiance, float scene_radius)
    : to_light_(-normalize(direction)),
      irradiance_(std::move(irradiance)),
      luminance_(spectrum_to_xyz(*irradiance_.spectrum()).y),
      scene_radius_(scene_radius) {}

std::optional<LightSample> DirectionalLight::sample(const Vec3&, const Vec2&,
                                                    const SampledWavelengths& lambda) const {
  LightSample s;
  s.wi = to_light_;
  s.distance = INFINITY;
  s.radiance = irradiance_.sample(lambda);  // a delta in direction: the irradiance it gives head-on
  s.pdf = 1.0f;
  s.delta = true;
  return s;
}

float DirectionalLight::power() const {
  return kPi * scene_radius_ * scene_radius_ * luminance_;
}

float DirectionalLight::importance(const Vec3&) const {
  return luminance_;  // the same everywhere
}

namespace {

BuiltLight build_directional(const LightContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const JsonFields& j = f.fields();
  const Vec3 direction = f.vec3("direction");
  if (!(length(direction) > 0.0f) || !std::isfinite(length(direction)))
    f.fail("direction", "gives no direction (zero, or a length that over- or underflows single precision)");
  return {std::make_unique<DirectionalLight>(direction,
                                             parse_spectrum(j.require("irradiance"), SpectrumRole::Illuminant,
                                                            j.child("irradiance"), ctx.dir),
                                             ctx.scene_radius),
          std::nullopt, "irradiance"};
}

}  // namespace

LightType directional_light_type() {
  return {"directional",
          "parallel light from infinitely far away (the sun): a surface facing it receives `irradiance`",
          {required_vec3_field("direction",
                               "[x, y, z]: where the light travels (from the light toward the scene)"),
           spectrum_field("irradiance", true,
                          "the irradiance on a surface facing the light (W m^-2 nm^-1 in relative units)")},
          false,
          build_directional};
}

}  // namespace ochre
