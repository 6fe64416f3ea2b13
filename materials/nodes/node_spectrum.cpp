// spectrum(file | name, column, extrapolate, scale): a tabulated or named spectrum, built once at compile
// time (the node is always folded: its consumers sample the pre-built spectrum).

#include <array>
#include <memory>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"
#include "materials/nodes/spectrum_source.h"
#include "spectra/scaled_spectrum.h"

namespace ochre {

namespace {

// Outside the CSV table: hold the end values or give 0 (docs/scene-format.md, 'Spectra').
constexpr std::array kExtrapolations{Choice{"clamp", TableExtrapolation::kClamp},
                                     Choice{"zero", TableExtrapolation::kZero}};

SpectrumPtr load(const PrepareArgs& args, bool from_file, TableExtrapolation extrapolation) {
  try {
    if (!from_file) return spectrum_by_name(args.params.at("name").get<std::string>());
    const std::string column =
        args.params.contains("column") ? args.params.at("column").get<std::string>() : "";
    return spectrum_from_file(args.params.at("file").get<std::string>(), column, args.resolver,
                              extrapolation);
  } catch (const std::runtime_error& e) {
    throw NodeError(from_file ? "file" : "name", e.what());
  }
}

Prepared prepare_spectrum(const PrepareArgs& args) {
  const TableExtrapolation extrapolation = args.params.contains("extrapolate")
                                               ? choice_value(args, "extrapolate", kExtrapolations)
                                               : TableExtrapolation::kClamp;
  const bool has_file = args.params.contains("file"), has_name = args.params.contains("name");
  if (has_file == has_name) throw NodeError(has_file ? "name" : "", "give exactly one of 'file' and 'name'");
  for (const char* file_only : {"column", "extrapolate"})
    if (has_name && args.params.contains(file_only))
      throw NodeError(file_only, std::string("'") + file_only + "' applies to 'file' only");

  SpectrumPtr s = load(args, has_file, extrapolation);
  const float scale = args.params.contains("scale") ? args.params.at("scale").get<float>() : 1.0f;
  if (scale != 1.0f) s = std::make_shared<ScaledSpectrum>(std::move(s), scale);

  Prepared p;
  p.constant_outputs = {NodeValue::of_spectrum(std::move(s))};
  return p;
}

}  // namespace

NodeDefinition spectrum_node() {
  NodeDefinition d;
  d.name = "spectrum";
  d.doc = "A spectrum from a CSV file or by name, times a scale. Give exactly one of file and name.";
  d.params = {string_param("file", "CSV file (wavelength in nm, then values), relative to the scene file"),
              string_param("name",
                           "named spectrum: CIE illuminants (\"D65\", \"A\", \"E\", ...) and others of "
                           "spectra/named_spectra.h"),
              string_param("column",
                           "value column of the CSV file, by header name (default: the first after "
                           "the wavelength)"),
              optional_choice_param("extrapolate", choice_names(kExtrapolations),
                                    "outside the CSV table: \"clamp\" (default) holds the end values, "
                                    "\"zero\" gives 0 (file only)"),
              number_param("scale", 1.0, 0.0, std::nullopt, "factor applied to every value (>= 0)")};
  d.outputs = {{"spectrum", SocketType::kSpectrum, false, "the spectrum"}};
  d.prepare = prepare_spectrum;
  return d;
}

}  // namespace ochre
