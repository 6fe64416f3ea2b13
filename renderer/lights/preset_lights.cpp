#include "renderer/lights/preset_lights.h"

#include <fmt/format.h>

#include "spectra/scaled_spectrum.h"

namespace ochre {

namespace {

// The largest relative standard deviation of a flicker: beyond it the log-normal factor is a spike train.
constexpr double kMaxRelativeStd = 10.0;

const FlamePreset& flame_preset(const JsonFields& f) {
  const std::string name = f.required_string("preset");
  const FlamePreset* preset = find_flame_preset(name);
  if (!preset)
    f.fail("preset", fmt::format("unknown flame preset '{}' (known: {})", name, flame_preset_names()));
  return *preset;
}

FlickerStats parse_flicker(const JsonFields& f, FlickerStats stats) {
  if (!f.has("flicker")) return stats;
  const JsonFields k(f.require("flicker"), f.child("flicker"));
  k.check_known({"relative_std", "frequency", "cct_std", "position_std"});
  stats.relative_std = static_cast<float>(k.number("relative_std", stats.relative_std, 0.0, kMaxRelativeStd));
  stats.corner_hz = static_cast<float>(k.number("frequency", stats.corner_hz, 0.0, 1e6, true));
  stats.cct_std_k = static_cast<float>(k.number("cct_std", stats.cct_std_k, 0.0, 1e4));
  stats.position_std_m = static_cast<float>(k.number("position_std", stats.position_std_m, 0.0, 1e30));
  return stats;
}

// The preset's spot light, aimed along `direction` from `position`.
std::unique_ptr<SpotLight> preset_spot(const JsonFields& f, const Vec3& position, const Vec3& direction) {
  const SpotPresetValues v = spot_preset_values(f);
  return std::make_unique<SpotLight>(position, direction, static_cast<float>(v.cone_angle),
                                     static_cast<float>(v.falloff_start), v.intensity);
}

}  // namespace

LoadedFlame load_flame(const JsonFields& f) {
  f.check_known({"type", "preset", "position", "radius", "cct", "intensity", "scale", "flicker"});
  const FlamePreset& preset = flame_preset(f);
  LoadedFlame out;
  FlameLight& flame = out.flame;
  flame.position = f.required_vec3("position");
  const auto radius = static_cast<float>(f.number("radius", preset.radius_m, 0.0, 1e30, true));
  // A blackbody below 500 K emits almost nothing visible (and below ~200 K nothing in single precision).
  flame.cct_k = static_cast<float>(f.number("cct", preset.cct_k, 500.0, 1e5));
  const double intensity = f.number("intensity", preset.intensity_cd, 0.0, 1e30);
  flame.intensity_cd = static_cast<float>(intensity * f.number("scale", 1.0, 0.0, 1e30));
  if (!std::isfinite(flame.intensity_cd)) f.fail("scale", "intensity x scale overflows single precision");
  flame.flicker = parse_flicker(f, preset.flicker);
  out.light =
      std::make_unique<SphereLight>(flame.position, radius, flame_spectrum(flame.cct_k, flame.intensity_cd));
  flame.light = out.light.get();
  return out;
}

SpotPresetValues spot_preset_values(const JsonFields& f) {
  const std::string name = f.required_string("preset");
  const SpotPreset* preset = find_spot_preset(name);
  if (!preset)
    f.fail("preset", fmt::format("unknown spot preset '{}' (known: {})", name, spot_preset_names()));
  if (f.has("intensity"))
    f.fail("intensity", "a preset sets the intensity: use \"scale\" to change it, or leave out \"preset\"");
  SpotPresetValues v;
  const double scale = f.number("scale", 1.0, 0.0, 1e30);
  v.intensity =
      std::make_shared<ScaledSpectrum>(preset->spectrum(), static_cast<float>(preset->intensity_cd * scale));
  v.cone_angle = f.number("cone_angle", preset->cone_angle_deg, 0.0, 180.0, true);
  v.falloff_start = f.number("falloff_start", std::min<double>(preset->falloff_start_deg, v.cone_angle), 0.0,
                             v.cone_angle, true);
  return v;
}

std::unique_ptr<SpotLight> load_camera_flash(const JsonFields& f, const Camera& camera) {
  f.check_known({"type", "preset", "offset", "scale", "cone_angle", "falloff_start", "polarizer"});
  const CameraBasis& c = camera.basis();
  // Default: 10 cm above the lens, as a hot-shoe flash.
  const Vec3 offset = f.vec3("offset", {0.0f, 0.1f, 0.0f});
  const Vec3 position = c.eye + c.right * offset.x + c.up * offset.y + c.forward * offset.z;
  if (!std::isfinite(length(position))) f.fail("offset", "puts the flash beyond single precision");
  if (!f.has("preset")) {
    nlohmann::json with_preset = f.json();
    with_preset["preset"] = "flash";
    const JsonFields defaulted(with_preset, f.where());
    return preset_spot(defaulted, position, c.forward);
  }
  return preset_spot(f, position, c.forward);
}

}  // namespace ochre
