#pragma once
// The fields a type of scene object takes (a shape, a light), declared once with their kind, default,
// range and help text. The loader reads an object through its type's declaration (DeclaredFields), so the
// default and range a value gets are the ones the declaration states, unknown keys are refused with the
// declared list, and docs/scene-format.md is checked against the declarations by a test.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/json/json_fields.h"

namespace ochre {

enum class FieldKind {
  kNumber,      // a JSON number in [min, max] (min exclusive when min_exclusive)
  kInteger,     // an integral JSON number in [min, max]
  kBoolean,     // true or false
  kString,      // a string (a file name, a preset name, ...)
  kChoice,      // one of `choices`
  kVec3,        // [x, y, z]
  kNumberPair,  // [a, b], each in [min, max]
  kSpectrum,    // a spectrum (docs/scene-format.md, "Spectra")
  kObject,      // an object or value the type reads itself (a transform, a "subdivision" block, ...)
};

struct FieldSpec {
  std::string name;
  FieldKind kind = FieldKind::kNumber;
  std::string help;  // one line for the docs
  bool required = false;
  std::string default_text;  // the default as docs/scene-format.md writes it ("1", "[2, 2]"); empty: none
  double fallback = 0.0;     // kNumber, kInteger, kBoolean (0 or 1)
  double min = kNoMinimum, max = kNoMaximum;
  bool min_exclusive = false;
  Vec3 fallback_vec3{};
  std::pair<double, double> fallback_pair{0.0, 0.0};
  std::vector<std::string> choices;  // kChoice; fallback_text is the default choice
  std::string fallback_text;         // kString, kChoice
  std::string pair_shape;            // kNumberPair: what the two numbers are ("[width, height]")
};

// Builders, one line per field in a type's declaration.
FieldSpec number_field(const char* name, double fallback, double min, double max, const char* help);
// A number > min.
FieldSpec positive_number_field(const char* name, double fallback, double max, const char* help);
// A number whose default the type computes (from a preset, another field): `default_text` says which.
FieldSpec computed_number_field(const char* name, const char* default_text, double min, double max,
                                bool min_exclusive, const char* help);
FieldSpec integer_field(const char* name, long long fallback, long long min, long long max, const char* help);
FieldSpec boolean_field(const char* name, bool fallback, const char* help);
FieldSpec string_field(const char* name, bool required, const char* help);
FieldSpec choice_field(const char* name, const char* fallback, std::vector<std::string> choices,
                       const char* help);
FieldSpec vec3_field(const char* name, Vec3 fallback, const char* help);
FieldSpec required_vec3_field(const char* name, const char* help);
// `shape` names the two numbers in messages ("[width, height]").
FieldSpec number_pair_field(const char* name, std::pair<double, double> fallback, double min, double max,
                            bool min_exclusive, const char* shape, const char* help);
FieldSpec spectrum_field(const char* name, bool required, const char* help);
// `default_text` may be empty (the field is optional and has no default, or the type says what it means).
FieldSpec object_field(const char* name, const char* default_text, const char* help);

// A JSON object read through a list of declarations: each accessor takes the declared default and range.
// Asking for a key that is not declared, or through the wrong accessor, is a programming error
// (std::logic_error), never bad input.
class DeclaredFields {
 public:
  DeclaredFields(const JsonFields& fields, const std::vector<const FieldSpec*>& specs);

  const JsonFields& fields() const { return fields_; }
  bool has(const char* key) const { return fields_.has(key); }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    fields_.fail(key, message);
  }
  // Refuses keys no declaration names, listing the declared names in their order.
  void check_known() const;

  double number(const char* key) const;
  // kNumber with a computed default (computed_number_field).
  double number_or(const char* key, double fallback) const;
  long long integer(const char* key) const;
  bool boolean(const char* key) const;
  std::string string(const char* key) const;  // kString: "" when absent and optional
  std::string choice(const char* key) const;
  Vec3 vec3(const char* key) const;
  // A kVec3 field that is a position: the numbers in double precision.
  Vec3d point(const char* key) const;
  std::pair<double, double> number_pair(const char* key) const;

 private:
  const FieldSpec& spec(const char* key, FieldKind kind) const;

  const JsonFields& fields_;
  std::vector<const FieldSpec*> specs_;
};

}  // namespace ochre
