#include "renderer/json/field_spec.h"

#include <fmt/format.h>

#include <stdexcept>

namespace ochre {

namespace {

FieldSpec field(const char* name, FieldKind kind, const char* help) {
  FieldSpec f;
  f.name = name;
  f.kind = kind;
  f.help = help;
  return f;
}

// Defaults as the docs write them: 1, 0.05, 1e+30 -> "1e30", 2^22 as an integer.
std::string number_text(double value) {
  std::string text = fmt::format("{:g}", value);
  const size_t plus = text.find("e+");
  if (plus != std::string::npos) text.erase(plus + 1, 1);
  return text;
}

}  // namespace

FieldSpec number_field(const char* name, double fallback, double min, double max, const char* help) {
  FieldSpec f = field(name, FieldKind::kNumber, help);
  f.fallback = fallback;
  f.default_text = number_text(fallback);
  f.min = min;
  f.max = max;
  return f;
}

FieldSpec positive_number_field(const char* name, double fallback, double max, const char* help) {
  FieldSpec f = number_field(name, fallback, 0.0, max, help);
  f.min_exclusive = true;
  return f;
}

FieldSpec computed_number_field(const char* name, const char* default_text, double min, double max,
                                bool min_exclusive, const char* help) {
  FieldSpec f = field(name, FieldKind::kNumber, help);
  f.default_text = default_text;
  f.min = min;
  f.max = max;
  f.min_exclusive = min_exclusive;
  return f;
}

FieldSpec integer_field(const char* name, long long fallback, long long min, long long max,
                        const char* help) {
  FieldSpec f = field(name, FieldKind::kInteger, help);
  f.fallback = static_cast<double>(fallback);
  f.default_text = std::to_string(fallback);
  f.min = static_cast<double>(min);
  f.max = static_cast<double>(max);
  return f;
}

FieldSpec boolean_field(const char* name, bool fallback, const char* help) {
  FieldSpec f = field(name, FieldKind::kBoolean, help);
  f.fallback = fallback ? 1.0 : 0.0;
  f.default_text = fallback ? "true" : "false";
  return f;
}

FieldSpec string_field(const char* name, bool required, const char* help) {
  FieldSpec f = field(name, FieldKind::kString, help);
  f.required = required;
  return f;
}

FieldSpec choice_field(const char* name, const char* fallback, std::vector<std::string> choices,
                       const char* help) {
  FieldSpec f = field(name, FieldKind::kChoice, help);
  f.choices = std::move(choices);
  f.fallback_text = fallback;
  f.default_text = fmt::format("\"{}\"", fallback);
  return f;
}

FieldSpec vec3_field(const char* name, Vec3 fallback, const char* help) {
  FieldSpec f = field(name, FieldKind::kVec3, help);
  f.fallback_vec3 = fallback;
  f.default_text =
      fmt::format("[{}, {}, {}]", number_text(fallback.x), number_text(fallback.y), number_text(fallback.z));
  return f;
}

FieldSpec required_vec3_field(const char* name, const char* help) {
  FieldSpec f = field(name, FieldKind::kVec3, help);
  f.required = true;
  return f;
}

FieldSpec number_pair_field(const char* name, std::pair<double, double> fallback, double min, double max,
                            bool min_exclusive, const char* shape, const char* help) {
  FieldSpec f = field(name, FieldKind::kNumberPair, help);
  f.fallback_pair = fallback;
  f.default_text = fmt::format("[{}, {}]", number_text(fallback.first), number_text(fallback.second));
  f.min = min;
  f.max = max;
  f.min_exclusive = min_exclusive;
  f.pair_shape = shape;
  return f;
}

FieldSpec spectrum_field(const char* name, bool required, const char* help) {
  FieldSpec f = field(name, FieldKind::kSpectrum, help);
  f.required = required;
  return f;
}

FieldSpec object_field(const char* name, const char* default_text, const char* help) {
  FieldSpec f = field(name, FieldKind::kObject, help);
  f.default_text = default_text;
  return f;
}

DeclaredFields::DeclaredFields(const JsonFields& fields, const std::vector<const FieldSpec*>& specs)
    : fields_(fields), specs_(specs) {}

void DeclaredFields::check_known() const {
  for (const auto& [key, value] : fields_.json().items()) {
    bool known = false;
    for (const FieldSpec* s : specs_) known = known || s->name == key;
    if (known) continue;
    std::string list;
    for (const FieldSpec* s : specs_) list += (list.empty() ? "" : ", ") + s->name;
    fields_.fail(key, fmt::format("unknown parameter '{}' (known: {})", key, list));
  }
}

const FieldSpec& DeclaredFields::spec(const char* key, FieldKind kind) const {
  for (const FieldSpec* s : specs_)
    if (s->name == key) {
      if (s->kind != kind) throw std::logic_error(fmt::format("field '{}' read as another kind", key));
      return *s;
    }
  throw std::logic_error(fmt::format("field '{}' is not declared", key));
}

double DeclaredFields::number(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kNumber);
  if (s.required) return fields_.required_number(key, s.min, s.max, s.min_exclusive);
  return fields_.number(key, s.fallback, s.min, s.max, s.min_exclusive);
}

double DeclaredFields::number_or(const char* key, double fallback) const {
  const FieldSpec& s = spec(key, FieldKind::kNumber);
  return fields_.number(key, fallback, s.min, s.max, s.min_exclusive);
}

long long DeclaredFields::integer(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kInteger);
  return fields_.integer(key, static_cast<long long>(s.fallback), static_cast<long long>(s.min),
                         static_cast<long long>(s.max));
}

bool DeclaredFields::boolean(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kBoolean);
  return fields_.boolean(key, s.fallback != 0.0);
}

std::string DeclaredFields::string(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kString);
  return s.required ? fields_.required_string(key) : fields_.string(key, "");
}

std::string DeclaredFields::choice(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kChoice);
  const std::string value = fields_.string(key, s.fallback_text);
  for (const std::string& c : s.choices)
    if (c == value) return value;
  std::string list;
  for (const std::string& c : s.choices) list += (list.empty() ? "" : ", ") + c;
  fields_.fail(key, fmt::format("unknown {} '{}' (known: {})", s.name, value, list));
}

Vec3 DeclaredFields::vec3(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kVec3);
  return s.required ? fields_.required_vec3(key) : fields_.vec3(key, s.fallback_vec3);
}

Vec3d DeclaredFields::point(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kVec3);
  return s.required ? fields_.required_vec3d(key) : fields_.vec3d(key, Vec3d(s.fallback_vec3));
}

std::pair<double, double> DeclaredFields::number_pair(const char* key) const {
  const FieldSpec& s = spec(key, FieldKind::kNumberPair);
  if (!fields_.has(key)) return s.fallback_pair;
  const std::string where = fields_.child(key);
  const nlohmann::json& pair = json_array(fields_.require(key), where, 2, s.pair_shape.c_str());
  return {json_number(pair[0], where + "[0]", s.min, s.max, s.min_exclusive),
          json_number(pair[1], where + "[1]", s.min, s.max, s.min_exclusive)};
}

}  // namespace ochre
