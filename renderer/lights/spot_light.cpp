#include "renderer/lights/spot_light.h"

#include <algorithm>
#include <cmath>

#include "renderer/json/spectrum_json.h"
#include "renderer/lights/light_type.h"
#include "renderer/lights/point_light.h"
#include "renderer/lights/preset_lights.h"
#include "spectra/cie.h"

namespace ochre {

SpotLight::SpotLight(const Vec3& position, const Vec3& direction, float cone_angle_deg,
                     float falloff_start_deg, SpectrumPtr intensity, Falloff falloff)
    : position_(position),
      direction_(normalize(direction)),
      cos_cone_(std::cos(cone_angle_deg * kPi / 180.0f)),
      cos_falloff_(std::cos(falloff_start_deg * kPi / 180.0f)),
      cone_(cone_angle_deg * kPi / 180.0f),
      falloff_start_(falloff_start_deg * kPi / 180.0f),
      falloff_(falloff),
      intensity_(std::move(intensity)),
      luminance_(spectrum_to_xyz(*intensity_.spectrum()).y) {}

float SpotLight::profile(const Vec3& direction) const {
  const float c = dot(direction_, direction);
  if (c >= cos_falloff_) return 1.0f;
  if (c <= cos_cone_) return 0.0f;
  if (falloff_ == Falloff::Linear) return (cone_ - std::acos(c)) / (cone_ - falloff_start_);
  const float t = (c - cos_cone_) / (cos_falloff_ - cos_cone_);
  return t * t * (3.0f - 2.0f * t);  // smoothstep
}

std::optional<LightSample> SpotLight::sample(const Vec3& ref, const Vec2&,
                                             const SampledWavelengths& lambda) const {
  auto s = sample_point_source(position_, ref);
  if (!s) return std::nullopt;
  const float k = profile(-s->wi);
  if (k <= 0.0f) return std::nullopt;
  s->radiance *= intensity_.sample(lambda) * k;
  return s;
}

float SpotLight::power() const {
  // Integral of the profile over the sphere: the full cone plus the ring. The smoothstep's mean over the
  // ring (in cos) is 1/2; the linear ramp integrates to ((g - b) cos b + sin b - sin g) / (g - b) in
  // 2 pi sin(theta) d(theta) from b = falloff_start to g = cone.
  const float ring =
      falloff_ == Falloff::Smoothstep || cone_ == falloff_start_
          ? 0.5f * (cos_falloff_ - cos_cone_)
          : ((cone_ - falloff_start_) * cos_falloff_ + std::sin(falloff_start_) - std::sin(cone_)) /
                (cone_ - falloff_start_);
  const float solid_angle = 2.0f * kPi * ((1.0f - cos_falloff_) + ring);
  return solid_angle * luminance_;
}

float SpotLight::importance(const Vec3& p) const {
  const Vec3 d = p - position_;
  const float d2 = length_squared(d);
  if (!(d2 > 0.0f)) return 0.0f;
  return luminance_ * profile(d / std::sqrt(d2)) / d2;
}

namespace {

BuiltLight build_spot(const LightContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const JsonFields& j = f.fields();
  const Vec3 position = ctx.position("position");
  if (f.has("direction") == f.has("target")) f.fail("", "give exactly one of \"direction\" or \"target\"");
  const char* aim = f.has("direction") ? "direction" : "target";
  // The aim at a target: from the two positions in double precision.
  const Vec3 direction = f.has("direction") ? j.required_vec3("direction")
                                            : (j.required_vec3d("target") - f.point("position")).to_float();
  if (!(length(direction) > 0.0f) || !std::isfinite(length(direction)))
    f.fail(aim, "gives no direction (zero, or a length that over- or underflows single precision)");
  const SpotLight::Falloff shape =
      f.choice("falloff") == "linear" ? SpotLight::Falloff::Linear : SpotLight::Falloff::Smoothstep;
  std::unique_ptr<SpotLight> light;
  if (f.has("preset")) {  // docs/lights.md
    const SpotPresetValues v = spot_preset_values(j);
    light = std::make_unique<SpotLight>(position, direction, static_cast<float>(v.cone_angle),
                                        static_cast<float>(v.falloff_start), v.intensity, shape);
  } else {
    if (f.has("scale"))
      f.fail("scale", "belongs to a \"preset\" light (scale an intensity spectrum with its own scale)");
    const double cone = f.number_or("cone_angle", 30.0);
    const double falloff = j.number("falloff_start", cone, 0.0, cone, true);
    light = std::make_unique<SpotLight>(
        position, direction, static_cast<float>(cone), static_cast<float>(falloff),
        parse_spectrum(j.require("intensity"), SpectrumRole::Illuminant, j.child("intensity"), ctx.dir),
        shape);
  }
  light->polarizer_axis = parse_light_polarizer(j);
  return {std::move(light), std::nullopt, f.has("preset") ? "scale" : "intensity"};
}

}  // namespace

LightType spot_light_type() {
  return {
      "spot",
      "a point light confined to a cone, with a smooth falloff at its edge",
      {required_vec3_field("position", "where it is"),
       object_field("direction", "", "[x, y, z]: where it points (or give `target`)"),
       object_field("target", "", "[x, y, z]: a point it aims at (or give `direction`)"),
       computed_number_field("cone_angle", "30, or the preset's", 0.0, 180.0, true,
                             "half-angle of the cone in degrees"),
       computed_number_field("falloff_start", "= `cone_angle`", 0.0, 180.0, true,
                             "half-angle where the falloff begins, at most `cone_angle`"),
       choice_field("falloff", "smoothstep", {"smoothstep", "linear"},
                    "the ramp: a smoothstep in the cosine (pbrt-v4's) or linear in the angle (Mitsuba 3's)"),
       spectrum_field("intensity", false, "radiant intensity on the axis (required without `preset`)"),
       string_field("preset", false,
                    "a spot preset (docs/lights.md): it gives the spectrum, intensity and cone"),
       number_field("scale", 1.0, 0.0, 1e30, "multiplies a preset's intensity"), polarizer_field()},
      false,
      build_spot};
}

}  // namespace ochre
