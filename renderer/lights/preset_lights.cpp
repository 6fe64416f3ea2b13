#include "renderer/lights/preset_lights.h"

#include <fmt/format.h>

#include "renderer/lights/light_presets.h"
#include "spectra/scaled_spectrum.h"

namespace ochre {

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

}  // namespace ochre
