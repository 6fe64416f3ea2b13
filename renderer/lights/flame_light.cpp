#include "renderer/lights/flame_light.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "renderer/lights/flicker_process.h"
#include "renderer/lights/light_type.h"

namespace ochre {

namespace {
// Independent random streams of one flame: intensity, colour temperature, position x, y, z.
constexpr uint64_t kStreamsPerFlame = 8;
enum Stream : uint64_t { kIntensity = 0, kCct = 1, kPositionX = 2 };
// A blackbody colder than this emits no visible light in single precision (docs/scene-format.md).
constexpr float kMinFlameCct = 500.0f;
}  // namespace

FlameState flame_state(const FlameLight& flame, uint64_t seed, uint64_t frame, double fps) {
  const FlickerStats& f = flame.flicker;
  const uint64_t base = static_cast<uint64_t>(flame.index) * kStreamsPerFlame;
  auto value = [&](uint64_t stream) {
    return ou_process_value(seed, base + stream, frame, fps, f.corner_hz);
  };
  FlameState s{flame.position, flame.cct_k, flame.intensity_cd};
  if (f.relative_std > 0.0f)
    s.intensity_cd =
        static_cast<float>(flame.intensity_cd * lognormal_factor(value(kIntensity), f.relative_std));
  if (f.cct_std_k > 0.0f)
    s.cct_k = std::max(kMinFlameCct, static_cast<float>(flame.cct_k + f.cct_std_k * value(kCct)));
  if (f.position_std_m > 0.0f)
    for (int axis = 0; axis < 3; ++axis)
      s.position[axis] +=
          static_cast<float>(f.position_std_m * value(kPositionX + static_cast<uint64_t>(axis)));
  return s;
}

void apply_flame_state(const FlameLight& flame, const FlameState& state) {
  flame.light->set_state(state.position, flame_spectrum(state.cct_k, state.intensity_cd));
}

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

BuiltLight build_flame(const LightContext& ctx) {
  const JsonFields& f = ctx.fields.fields();
  const FlamePreset& preset = flame_preset(f);
  FlameLight flame;
  flame.position = (f.required_vec3d("position") - ctx.origin).to_float();
  const auto radius = static_cast<float>(f.number("radius", preset.radius_m, 0.0, 1e30, true));
  // A blackbody below 500 K emits almost nothing visible (and below ~200 K nothing in single precision).
  flame.cct_k = static_cast<float>(f.number("cct", preset.cct_k, 500.0, 1e5));
  const double intensity = f.number("intensity", preset.intensity_cd, 0.0, 1e30);
  flame.intensity_cd = static_cast<float>(intensity * f.number("scale", 1.0, 0.0, 1e30));
  if (!std::isfinite(flame.intensity_cd)) f.fail("scale", "intensity x scale overflows single precision");
  flame.flicker = parse_flicker(f, preset.flicker);
  auto light =
      std::make_unique<SphereLight>(flame.position, radius, flame_spectrum(flame.cct_k, flame.intensity_cd));
  flame.light = light.get();
  return {std::move(light), flame, f.has("scale") ? "scale" : "intensity"};
}

}  // namespace

LightType flame_light_type() {
  return {
      "flame",
      "a sphere light with a blackbody spectrum after the Palaeolithic lighting experiments of "
      "Medina-Alcaide "
      "et al. 2021, flickering in frame sequences",
      {string_field("preset", true, "torch, torch_juniper, grease_lamp or fireplace (docs/lights.md)"),
       required_vec3_field("position", "the flame's mean position"),
       computed_number_field("radius", "the preset's", 0.0, 1e30, true, "the sphere's radius in metres"),
       computed_number_field("cct", "the preset's", 500.0, 1e5, false, "mean colour temperature in kelvin"),
       computed_number_field("intensity", "the preset's", 0.0, 1e30, false,
                             "mean luminous intensity in candela"),
       number_field("scale", 1.0, 0.0, 1e30, "multiplies the intensity"),
       object_field(
           "flicker", "the preset's",
           "{\"relative_std\", \"frequency\", \"cct_std\", \"position_std\"}: the flicker's statistics")},
      false,
      build_flame};
}

}  // namespace ochre
