#pragma once
// Builders of the socket and parameter definitions that node types declare (node_definition.h), so that
// each closure lists its inputs and parameters in one line apiece.

#include <optional>
#include <string>
#include <vector>

#include "materials/nodes/node_definition.h"

namespace ochre {

// A linkable number (SocketType kFloat or kSpectrum) with a default; a bound makes linked values clamped
// to [min, max] at run time and constants outside it an error.
SocketDef float_input(const char* name, SocketType type, float fallback, std::optional<float> min,
                      std::optional<float> max, const char* doc);
// A spectrum input >= 0 whose default is the named spectrum `spectrum_name` (spectra/named_spectra.h).
SocketDef named_spectrum_input(const char* name, const char* spectrum_name, const char* doc);
// An input that, when not given, is linked to a hidden node of type `default_node` ("uv", "position").
SocketDef context_input(const char* name, SocketType type, const char* default_node, const char* doc);
// A constant number parameter in [min, max].
ParamDef number_param(const char* name, double fallback, double min, double max, const char* doc);
// An integer parameter in [min, max] (no upper bound when max is empty).
ParamDef integer_param(const char* name, int fallback, int min, std::optional<int> max, const char* doc);
// A required parameter written as a value literal (a float, [r, g, b] or {"vector": [x, y, z]}).
ParamDef required_value_param(const char* name, const char* doc);
// A string parameter that must be one of `choices`.
ParamDef choice_param(const char* name, const char* fallback, std::vector<std::string> choices,
                      const char* doc);
// A free string parameter (a file name, ...), empty by default.
ParamDef string_param(const char* name, const char* doc);

}  // namespace ochre
