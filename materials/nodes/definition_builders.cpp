#include "materials/nodes/definition_builders.h"

#include <utility>

#include "spectra/named_spectra.h"

namespace ochre {

namespace {

SocketDef make_socket(const char* name, SocketType type, NodeValue fallback, SpectralRole role,
                      InputRange range, const char* doc) {
  SocketDef s;
  s.name = name;
  s.type = type;
  s.default_value = std::move(fallback);
  s.role = role;
  s.min = range.min;
  s.max = range.max;
  s.clamped = range.clamped;
  s.doc = doc;
  return s;
}

ParamDef make_param(const char* name, ParamKind kind, nlohmann::json fallback, const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = kind;
  p.default_value = std::move(fallback);
  p.doc = doc;
  return p;
}

}  // namespace

InputRange clamped_range(std::optional<float> min, std::optional<float> max) {
  return {min, max, true};
}

InputRange constant_range(std::optional<float> min, std::optional<float> max) {
  return {min, max, false};
}

SocketDef float_input(const char* name, SocketType type, float fallback, InputRange range, const char* doc) {
  return make_socket(name, type, NodeValue::of_float(fallback), SpectralRole::kNone, range, doc);
}

SocketDef reflectance_input(const char* name, float fallback, InputRange range, const char* doc) {
  return make_socket(name, SocketType::kSpectrum, NodeValue::of_float(fallback), SpectralRole::kReflectance,
                     range, doc);
}

SocketDef colour_input(const char* name, SocketType type, const RGB& fallback, SpectralRole role,
                       InputRange range, const char* doc) {
  return make_socket(name, type, NodeValue::of_colour(fallback), role, range, doc);
}

SocketDef vector_input(const char* name, const Vec3& fallback, const char* doc) {
  return make_socket(name, SocketType::kVector, NodeValue::of_vector(fallback), SpectralRole::kNone,
                     kAnyValue, doc);
}

SocketDef named_spectrum_input(const char* name, const char* spectrum_name, const char* doc) {
  return make_socket(name, SocketType::kSpectrum, NodeValue::of_spectrum(named_spectrum(spectrum_name)),
                     SpectralRole::kNone, constant_range(0.0f, std::nullopt), doc);
}

SocketDef context_input(const char* name, SocketType type, const char* default_node, const char* doc) {
  SocketDef s = make_socket(name, type, NodeValue{}, SpectralRole::kNone, kAnyValue, doc);
  s.default_node = default_node;
  return s;
}

SocketDef operand_input(const char* name, float fallback, const char* doc) {
  SocketDef s = make_socket(name, SocketType::kFloat, NodeValue::of_float(fallback), SpectralRole::kInherit,
                            kAnyValue, doc);
  s.polymorphic = true;
  return s;
}

ParamDef number_param(const char* name, double fallback, double min, std::optional<double> max,
                      const char* doc) {
  ParamDef p = make_param(name, ParamKind::kFloat, fallback, doc);
  p.min = min;
  p.max = max;
  return p;
}

ParamDef integer_param(const char* name, int fallback, int min, std::optional<int> max, const char* doc) {
  ParamDef p = make_param(name, ParamKind::kInt, fallback, doc);
  p.min = min;
  if (max) p.max = *max;
  return p;
}

ParamDef required_value_param(const char* name, const char* doc) {
  ParamDef p = make_param(name, ParamKind::kValue, nullptr, doc);
  p.required = true;
  return p;
}

ParamDef choice_param(const char* name, const char* fallback, std::vector<std::string> choices,
                      const char* doc) {
  ParamDef p = make_param(name, ParamKind::kString, fallback, doc);
  p.choices = std::move(choices);
  return p;
}

ParamDef optional_choice_param(const char* name, std::vector<std::string> choices, const char* doc) {
  ParamDef p = make_param(name, ParamKind::kString, nullptr, doc);
  p.choices = std::move(choices);
  return p;
}

ParamDef string_param(const char* name, const char* doc) {
  return make_param(name, ParamKind::kString, nullptr, doc);
}

ParamDef required_string_param(const char* name, const char* doc) {
  ParamDef p = string_param(name, doc);
  p.required = true;
  return p;
}

ParamDef research_param(ParamDef p) {
  p.research = true;
  p.doc = "research: " + p.doc;
  return p;
}

std::vector<ParamDef> research_params(std::vector<ParamDef> params) {
  for (ParamDef& p : params) p = research_param(std::move(p));
  return params;
}

}  // namespace ochre
