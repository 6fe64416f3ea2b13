#pragma once
// Builders of the socket and parameter definitions that node types declare (node_definition.h), so that
// each node lists its inputs and parameters in one line apiece and no definition sets fields by hand.

#include <optional>
#include <string>
#include <vector>

#include "materials/core/vec3.h"
#include "materials/nodes/node_definition.h"
#include "spectra/color_types.h"

namespace ochre {

// The values an input accepts: a constant outside [min, max] is an error (also one that constant folding
// produces); `clamped` says that the node clamps a linked value into the range at run time
// (SocketDef::clamped, which documents what the node's eval does).
struct InputRange {
  std::optional<float> min, max;
  bool clamped = false;
};
// Any value.
inline constexpr InputRange kAnyValue{};
// Constants within [min, max] (a side left empty is open); linked values are clamped into it.
InputRange clamped_range(std::optional<float> min, std::optional<float> max);
// Constants within [min, max]; linked values reach the node unchanged (the node copes with any value).
InputRange constant_range(std::optional<float> min, std::optional<float> max);

// A linkable number (SocketType kFloat or kSpectrum) with a default.
SocketDef float_input(const char* name, SocketType type, float fallback, InputRange range, const char* doc);
// A spectrum input with the reflectance role (a colour is upsampled as a reflectance) and a grey default.
SocketDef reflectance_input(const char* name, float fallback, InputRange range, const char* doc);
// An input whose default is a colour (SocketType kColour, or kSpectrum upsampled by `role`).
SocketDef colour_input(const char* name, SocketType type, const RGB& fallback, SpectralRole role,
                       InputRange range, const char* doc);
// A vector input with a default.
SocketDef vector_input(const char* name, const Vec3& fallback, const char* doc);
// A spectrum input >= 0 whose default is the named spectrum `spectrum_name` (spectra/named_spectra.h).
SocketDef named_spectrum_input(const char* name, const char* spectrum_name, const char* doc);
// An input that, when not given, is linked to a hidden node of type `default_node` ("uv", "position").
SocketDef context_input(const char* name, SocketType type, const char* default_node, const char* doc);
// An operand of a math node: its type comes from what is connected (resolve_types), and a colour it
// combines with a spectrum takes the role of the inputs the result reaches (docs/nodes.md, 'Spectral
// roles').
SocketDef operand_input(const char* name, float fallback, const char* doc);

// A constant number parameter in [min, max] (no upper bound when max is empty).
ParamDef number_param(const char* name, double fallback, double min, std::optional<double> max,
                      const char* doc);
// An integer parameter in [min, max] (no upper bound when max is empty); [0, 1] for a switch.
ParamDef integer_param(const char* name, int fallback, int min, std::optional<int> max, const char* doc);
// A required parameter written as a value literal (a float, [r, g, b] or {"vector": [x, y, z]}).
ParamDef required_value_param(const char* name, const char* doc);
// A string parameter that must be one of `choices`, `fallback` when not given.
ParamDef choice_param(const char* name, const char* fallback, std::vector<std::string> choices,
                      const char* doc);
// A string parameter that must be one of `choices` when given, and has no default (absent means
// something of its own, such as "use the eta and k inputs").
ParamDef optional_choice_param(const char* name, std::vector<std::string> choices, const char* doc);
// A free string parameter (a file name, ...), empty by default.
ParamDef string_param(const char* name, const char* doc);
// A free string parameter that every node of the type must be given (a texture's file).
ParamDef required_string_param(const char* name, const char* doc);
// `p` marked as a research variant (ParamDef::research), its doc prefixed with "research: ".
ParamDef research_param(ParamDef p);
// Each of `params` marked so.
std::vector<ParamDef> research_params(std::vector<ParamDef> params);

}  // namespace ochre
