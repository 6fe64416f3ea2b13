#include "materials/nodes/spectrum_source.h"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "materials/core/single_precision.h"
#include "materials/nodes/resource_resolver.h"
#include "materials/nodes/json_literal.h"
#include "spectra/blackbody_spectrum.h"
#include "spectra/cie.h"
#include "spectra/named_spectra.h"
#include "spectra/scaled_spectrum.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

SpectrumPtr spectrum_by_name(const std::string& name) {
  try {
    return named_spectrum(name);
  } catch (const std::exception& e) {
    throw std::runtime_error("spectrum name '" + name + "': " + e.what());
  }
}

SpectrumPtr spectrum_from_file(const std::string& file, const std::string& column,
                               const ResourceResolver& resolver, TableExtrapolation extrapolation) {
  const std::filesystem::path path = resolver.resolve(file);
  try {
    return column.empty() ? load_spectrum_csv(path, std::size_t{1}, extrapolation)
                          : load_spectrum_csv(path, std::string_view(column), extrapolation);
  } catch (const std::exception& e) {
    // The loaders name the file already, but say which one the scene meant in every case.
    throw std::runtime_error("cannot load spectrum file '" + path.string() + "': " + e.what());
  }
}

TableExtrapolation table_extrapolation(const nlohmann::json& value) {
  const std::optional<TableExtrapolation> e =
      value.is_string() ? table_extrapolation_from_name(value.get<std::string>()) : std::nullopt;
  if (!e) throw std::runtime_error("'extrapolate' must be \"clamp\" or \"zero\", got " + value.dump());
  return *e;
}

SpectrumPtr blackbody_unit_luminance(double kelvin) {
  auto planck = std::make_shared<BlackbodySpectrum>(static_cast<float>(kelvin));
  const float luminance = spectrum_to_xyz(*planck).y;
  // Below a few hundred kelvin the visible part of Planck's law underflows single precision.
  if (!(luminance > 0.0f) || !std::isfinite(1.0f / luminance))
    throw std::invalid_argument("a blackbody at " + number_text(kelvin) +
                                " K emits no visible light in single precision");
  return std::make_shared<ScaledSpectrum>(planck, 1.0f / luminance);
}

bool is_spectrum_object(const nlohmann::json& j) {
  return j.is_object() &&
         (j.contains("name") || j.contains("file") || j.contains("blackbody") || j.contains("wavelengths"));
}

namespace {

std::string string_field(const nlohmann::json& j, const char* key) {
  if (!j.at(key).is_string()) throw SpectrumObjectError(key, std::string("'") + key + "' must be a string");
  return j.at(key).get<std::string>();
}

double number_field(const nlohmann::json& j, const char* key) {
  const nlohmann::json& v = j.at(key);
  if (!v.is_number())
    throw SpectrumObjectError(key, std::string("'") + key + "' must be a number, got " + json_excerpt(v));
  if (const std::string problem = single_precision_problem(v.get<double>()); !problem.empty())
    throw SpectrumObjectError(key, std::string("'") + key + "' must be a finite number (got " +
                                       json_excerpt(v) + ", " + problem + ")");
  return v.get<double>();
}

// "wavelengths": [nm, ...] with "values": [v, ...] of the same length: a table written in the scene.
std::vector<float> number_list(const nlohmann::json& j, const char* key) {
  const nlohmann::json& list = j.at(key);
  if (!list.is_array())
    throw SpectrumObjectError(key, std::string("'") + key + "' must be an array of numbers");
  std::vector<float> numbers;
  numbers.reserve(list.size());
  for (size_t i = 0; i < list.size(); ++i) {
    const nlohmann::json& v = list[i];
    const std::string at = std::string(key) + "[" + std::to_string(i) + "]";
    if (!v.is_number()) throw SpectrumObjectError(at, "must be a number, got " + json_excerpt(v));
    if (const std::string problem = single_precision_problem(v.get<double>()); !problem.empty())
      throw SpectrumObjectError(at, "must be a finite number (got " + json_excerpt(v) + ", " + problem + ")");
    numbers.push_back(static_cast<float>(v.get<double>()));
  }
  return numbers;
}

SpectrumPtr inline_table(const nlohmann::json& j, TableExtrapolation extrapolation) {
  if (!j.contains("values")) throw SpectrumObjectError("wavelengths", "'wavelengths' needs 'values'");
  std::vector<float> lambda = number_list(j, "wavelengths"), values = number_list(j, "values");
  if (lambda.size() != values.size())
    throw SpectrumObjectError("values", "'values' must have as many entries as 'wavelengths' (" +
                                            std::to_string(values.size()) + " and " +
                                            std::to_string(lambda.size()) + ")");
  try {
    return std::make_shared<TabulatedSpectrum>(std::move(lambda), std::move(values), extrapolation);
  } catch (const std::invalid_argument& e) {
    throw SpectrumObjectError("wavelengths", e.what());
  }
}

}  // namespace

SpectrumPtr spectrum_from_object(const nlohmann::json& j, const ResourceResolver& resolver) {
  const int kinds =
      j.contains("name") + j.contains("file") + j.contains("blackbody") + j.contains("wavelengths");
  if (kinds != 1)
    throw SpectrumObjectError(
        "",
        "a spectrum is written {\"name\": \"D65\"}, {\"file\": \"x.csv\"[, \"column\": ...][, "
        "\"extrapolate\": \"clamp\"|\"zero\"]}, {\"wavelengths\": [nm, ...], \"values\": [...][, "
        "\"extrapolate\": ...]} or {\"blackbody\": kelvin}, with an optional \"scale\"");
  for (const auto& [key, value] : j.items())
    if (key != "name" && key != "file" && key != "column" && key != "extrapolate" && key != "blackbody" &&
        key != "scale" && key != "wavelengths" && key != "values")
      throw SpectrumObjectError(key, "unknown key '" + key +
                                         "' in a spectrum (known: name, file, column, wavelengths, values, "
                                         "extrapolate, blackbody, scale)");
  if (j.contains("column") && !j.contains("file"))
    throw SpectrumObjectError("column", "'column' needs 'file'");
  if (j.contains("extrapolate") && !j.contains("file") && !j.contains("wavelengths"))
    throw SpectrumObjectError("extrapolate", "'extrapolate' needs 'file' or 'wavelengths'");
  if (j.contains("values") && !j.contains("wavelengths"))
    throw SpectrumObjectError("values", "'values' needs 'wavelengths'");
  TableExtrapolation extrapolation = TableExtrapolation::kClamp;
  if (j.contains("extrapolate")) {
    try {
      extrapolation = table_extrapolation(j.at("extrapolate"));
    } catch (const std::runtime_error& e) {
      throw SpectrumObjectError("extrapolate", e.what());
    }
  }

  SpectrumPtr base;
  if (j.contains("name")) {
    try {
      base = spectrum_by_name(string_field(j, "name"));
    } catch (const SpectrumObjectError&) {
      throw;
    } catch (const std::exception& e) {
      throw SpectrumObjectError("name", e.what());
    }
  } else if (j.contains("blackbody")) {
    const double kelvin = number_field(j, "blackbody");
    if (!(kelvin > 0.0) || kelvin > 1e6)
      throw SpectrumObjectError("blackbody",
                                "temperature must be in (0, 1e6] K (got " + number_text(kelvin) + ")");
    try {
      base = blackbody_unit_luminance(kelvin);
    } catch (const std::invalid_argument& e) {
      throw SpectrumObjectError("blackbody", e.what());
    }
  } else if (j.contains("wavelengths")) {
    base = inline_table(j, extrapolation);
  } else {
    const std::string column = j.contains("column") ? string_field(j, "column") : "";
    try {
      base = spectrum_from_file(string_field(j, "file"), column, resolver, extrapolation);
    } catch (const SpectrumObjectError&) {
      throw;
    } catch (const std::exception& e) {
      throw SpectrumObjectError("file", e.what());
    }
  }
  if (!j.contains("scale")) return base;
  const double scale = number_field(j, "scale");
  if (scale < 0.0)
    throw SpectrumObjectError("scale", "'scale' must be >= 0 (got " + number_text(scale) + ")");
  return std::make_shared<ScaledSpectrum>(base, static_cast<float>(scale));
}

}  // namespace ochre
