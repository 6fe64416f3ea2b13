#pragma once
// Spectra named in a scene, by name or by CSV file; shared by the spectrum node and by spectrum
// literals ({"name": "D65"}, {"file": "red.csv"}) on any input.

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "spectra/spectrum.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

class ResourceResolver;

// named_spectrum(name); throws std::runtime_error listing the problem for an unknown name.
SpectrumPtr spectrum_by_name(const std::string& name);
// The CSV file's first value column, or `column` when not empty, with the given behaviour outside the
// table. Throws std::runtime_error whose message contains the resolved path.
SpectrumPtr spectrum_from_file(const std::string& file, const std::string& column,
                               const ResourceResolver& resolver,
                               TableExtrapolation extrapolation = TableExtrapolation::kClamp);

// The "extrapolate" setting of a tabulated spectrum: "clamp" or "zero". Throws std::runtime_error naming
// the allowed values otherwise.
TableExtrapolation table_extrapolation(const nlohmann::json& value);

// A blackbody at `kelvin` normalised to luminance 1 (like the named illuminants).
SpectrumPtr blackbody_unit_luminance(double kelvin);

// Keys a spectrum object may have.
bool is_spectrum_object(const nlohmann::json& j);
// A spectrum written as an object, the one form shared by material inputs and lights:
// {"name": "D65"} | {"file": "x.csv", "column": "c", "extrapolate": "zero"} | {"blackbody": 2700}, each
// with an optional "scale" >= 0. Throws SpectrumObjectError naming the offending key.
SpectrumPtr spectrum_from_object(const nlohmann::json& j, const ResourceResolver& resolver);

struct SpectrumObjectError : std::runtime_error {
  SpectrumObjectError(std::string key_, const std::string& what)
      : std::runtime_error(what), key(std::move(key_)) {}
  std::string key;  // "name", "file", "blackbody", "scale", "extrapolate", ... ("" for the object as a whole)
};

}  // namespace ochre
