#include "renderer/lights/light_presets.h"

#include <cmath>
#include <memory>

#include "spectra/blackbody_spectrum.h"
#include "spectra/cie.h"
#include "spectra/named_spectra.h"
#include "spectra/scaled_spectrum.h"

namespace ochre {

namespace {

// Puffing (flicker) frequency of a buoyant diffusion flame of base diameter D metres: f = 1.5 / sqrt(D) Hz
// (Cetegen & Ahmed 1993, Combustion and Flame 93: 157-184). Our flicker corner frequencies use it with
// the flame sizes below (estimates).
float puffing_hz(float diameter_m) {
  return 1.5f / std::sqrt(diameter_m);
}

// Sources, per figure (docs/lights.md has the table):
//   [M]  Medina-Alcaide et al. 2021: torch durations 21-61 min (mean 41), a torch gives almost five times
//        the light of a double-wicked grease lamp, grease lamps burn steadily for over an hour, the
//        fireplace went out after about 30 minutes;
//   [E]  our estimate: colour temperatures of soot-radiating flames (candle and wood flames 1700-1900 K),
//        a grease lamp about as bright as a candle (1 cd), flame sizes, flicker depths; the paper gives
//        no spectra, CCTs we could check, nor flicker statistics.
const FlamePreset kFlames[] = {
    // name           CCT [E]  cd [M x E]  radius [E]  min [M]  flicker: rel. std [E], corner [E, puffing law]
    {"torch", 1700.0f, 5.0f, 0.08f, 41.0f, {0.25f, puffing_hz(0.08f), 0.0f, 0.0f}},
    {"torch_juniper", 1700.0f, 5.0f, 0.08f, 41.0f, {0.25f, puffing_hz(0.08f), 0.0f, 0.0f}},
    {"grease_lamp", 1850.0f, 1.0f, 0.015f, 60.0f, {0.05f, puffing_hz(0.02f), 0.0f, 0.0f}},
    {"fireplace", 1650.0f, 12.0f, 0.25f, 30.0f, {0.20f, puffing_hz(0.4f), 0.0f, 0.0f}},
};

SpectrumPtr led_spectrum() {
  return normalized_to_unit_luminance(named_spectrum("LED-4100K-model"));
}
SpectrumPtr flash_spectrum() {
  return normalized_to_unit_luminance(std::make_shared<BlackbodySpectrum>(5500.0f));
}

// LED work light: a 1000 lm head spread over a 60 degree half-angle cone has 1000 / (2 pi (1 - cos 60))
// = 318 cd on the axis [E]. Flash: an estimate of the mean intensity over the flash duration, relative
// to the flames (what matters for a render is the ratio between lights) [E]; 35 degree half-angle covers
// a 28 mm lens on full frame.
const SpotPreset kSpots[] = {
    {"led_work_light", 318.0f, 60.0f, 45.0f, &led_spectrum},
    {"flash", 2000.0f, 35.0f, 30.0f, &flash_spectrum},
};

template <class Table>
std::string names_of(const Table& table) {
  std::string names;
  for (const auto& p : table) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

}  // namespace

const FlamePreset* find_flame_preset(std::string_view name) {
  for (const FlamePreset& p : kFlames)
    if (p.name == name) return &p;
  return nullptr;
}

const SpotPreset* find_spot_preset(std::string_view name) {
  for (const SpotPreset& p : kSpots)
    if (p.name == name) return &p;
  return nullptr;
}

std::string flame_preset_names() {
  return names_of(kFlames);
}
std::string spot_preset_names() {
  return names_of(kSpots);
}

SpectrumPtr flame_spectrum(float cct_k, float intensity_cd) {
  return std::make_shared<ScaledSpectrum>(
      normalized_to_unit_luminance(std::make_shared<BlackbodySpectrum>(cct_k)), intensity_cd);
}

}  // namespace ochre
