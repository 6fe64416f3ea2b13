#include "materials/nodes/definition_builders.h"

#include <utility>

#include "spectra/named_spectra.h"

namespace ochre {

SocketDef float_input(const char* name, SocketType type, float fallback, std::optional<float> min,
                      std::optional<float> max, const char* doc) {
  SocketDef s;
  s.name = name;
  s.type = type;
  s.default_value = NodeValue::of_float(fallback);
  s.min = min;
  s.max = max;
  s.clamped = min.has_value() || max.has_value();
  s.doc = doc;
  return s;
}

SocketDef named_spectrum_input(const char* name, const char* spectrum_name, const char* doc) {
  SocketDef s;
  s.name = name;
  s.type = SocketType::kSpectrum;
  s.default_value = NodeValue::of_spectrum(named_spectrum(spectrum_name));
  s.role = SpectralRole::kNone;
  s.min = 0.0f;
  s.doc = doc;
  return s;
}

SocketDef context_input(const char* name, SocketType type, const char* default_node, const char* doc) {
  SocketDef s;
  s.name = name;
  s.type = type;
  s.default_node = default_node;
  s.doc = doc;
  return s;
}

ParamDef integer_param(const char* name, int fallback, int min, std::optional<int> max, const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = ParamKind::kInt;
  p.default_value = fallback;
  p.min = min;
  if (max) p.max = *max;
  p.doc = doc;
  return p;
}

ParamDef required_value_param(const char* name, const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = ParamKind::kValue;
  p.required = true;
  p.doc = doc;
  return p;
}

ParamDef number_param(const char* name, double fallback, double min, double max, const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = ParamKind::kFloat;
  p.default_value = fallback;
  p.min = min;
  p.max = max;
  p.doc = doc;
  return p;
}

ParamDef choice_param(const char* name, const char* fallback, std::vector<std::string> choices,
                      const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = ParamKind::kString;
  p.default_value = fallback;
  p.choices = std::move(choices);
  p.doc = doc;
  return p;
}

ParamDef string_param(const char* name, const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = ParamKind::kString;
  p.doc = doc;
  return p;
}

}  // namespace ochre
