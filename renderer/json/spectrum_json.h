#pragma once
// Spectra given in a scene's lights and film settings:
//   2.5                          constant
//   [r, g, b]                    linear Rec.709 RGB (illuminant: D65-based, reflectance: bounded)
//   {"name": "D65", "scale": s}  named spectrum (illuminants have luminance 1 before scale)
//   {"blackbody": 2700, "scale": s}  Planck spectrum normalised to luminance 1
//   {"file": "x.csv", "column": "value", "extrapolate": "zero", "scale": s}  tabulated, used as given (path
//                                relative to the scene; outside the table: "clamp" (default) or "zero")
// Every form must be >= 0 at every wavelength: an InputError names `where` (and the CSV file and the
// wavelength of its first negative entry).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "spectra/spectrum.h"

namespace ochre {

enum class SpectrumRole { Illuminant, Reflectance, Unbounded };

SpectrumPtr parse_spectrum(const nlohmann::json& value, SpectrumRole role, const std::string& where,
                           const std::filesystem::path& scene_dir);

}  // namespace ochre
