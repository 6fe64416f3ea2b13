#include "renderer/lights/point_light.h"

#include <algorithm>

#include "renderer/json/spectrum_json.h"
#include "renderer/lights/light_type.h"
#include "spectra/cie.h"

namespace ochre {

PointLight::PointLight(const Vec3& position, SpectrumPtr intensity)
    : position_(position),
      intensity_(std::move(intensity)),
      luminance_(spectrum_to_xyz(*intensity_.spectrum()).y) {}

std::optional<LightSample> sample_point_source(const Vec3& position, const Vec3& ref) {
  const Vec3 d = position - ref;
  const float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return std::nullopt;
  LightSample s;
  s.distance = std::sqrt(dist2);
  s.wi = d / s.distance;
  s.radiance = SampledSpectrum(1.0f / dist2);  // inverse-square law
  s.pdf = 1.0f;
  s.delta = true;
  return s;
}

std::optional<LightSample> PointLight::sample(const Vec3& ref, const Vec2&,
                                              const SampledWavelengths& lambda) const {
  auto s = sample_point_source(position_, ref);
  if (s) s->radiance *= intensity_.sample(lambda);
  return s;
}

float PointLight::power() const {
  return 4.0f * kPi * luminance_;
}

float PointLight::importance(const Vec3& p) const {
  return luminance_ / std::max(length_squared(position_ - p), 1e-12f);  // inverse-square law
}

namespace {

BuiltLight build_point(const LightContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const JsonFields& j = f.fields();
  auto light = std::make_unique<PointLight>(
      ctx.position("position"),
      parse_spectrum(j.require("intensity"), SpectrumRole::Illuminant, j.child("intensity"), ctx.dir));
  light->polarizer_axis = parse_light_polarizer(j);
  return {std::move(light), std::nullopt, "intensity"};
}

}  // namespace

LightType point_light_type() {
  return {"point",
          "isotropic point light",
          {required_vec3_field("position", "where it is"),
           spectrum_field("intensity", true, "radiant intensity spectrum (W sr^-1 nm^-1 in relative units)"),
           polarizer_field()},
          false,
          build_point};
}

}  // namespace ochre
