#pragma once
// One Mitsuba object element (<bsdf>, <shape>, <emitter>, <sensor>, ...) and its properties, read by name
// (docs/mitsuba-import.md). Every read marks what it read; finish() refuses whatever was not read, naming
// the element, the property and what the object supports, so nothing in a scene is silently dropped.

#include <optional>
#include <string>
#include <vector>

#include "renderer/loader/mitsuba/mitsuba_values.h"
#include "renderer/loader/mitsuba/mitsuba_xml.h"

namespace ochre {

class MitsubaObject {
 public:
  MitsubaObject(const MitsubaElement& element, const MitsubaDocument& document);

  const MitsubaElement& element() const { return element_; }
  const MitsubaDocument& document() const { return document_; }
  // The type attribute ("diffuse", "obj", ...).
  const std::string& type() const { return type_; }
  [[noreturn]] void fail(const std::string& message) const { fail_at(element_, message); }

  bool has(const std::string& name) const;
  // The element that gives property `name`: a property element (<float name="...">, <rgb>, <spectrum>, ...),
  // a named nested object (<texture name="reflectance">) or the target of <ref name="..." id="..."/>;
  // nullptr when absent.
  const MitsubaElement* get(const std::string& name);

  // Typed properties: <float> or <integer> for numbers, <integer> for integers, ... A property of another
  // kind is an error naming the expected kind.
  std::optional<double> number(const std::string& name);
  double number(const std::string& name, double fallback) { return number(name).value_or(fallback); }
  std::optional<long long> integer(const std::string& name);
  bool boolean(const std::string& name, bool fallback);
  std::optional<std::string> string(const std::string& name);
  std::string string(const std::string& name, const std::string& fallback) {
    return string(name).value_or(fallback);
  }
  // A <string> the object cannot do without (a file name): its absence is an error showing how to write it.
  std::string required_string(const std::string& name);
  std::optional<Vec3d> point(const std::string& name);
  std::optional<Matrix4d> transform(const std::string& name);
  // A colour, spectrum or number property (textures are refused here).
  std::optional<nlohmann::json> colour(const std::string& name, MitsubaColourRole role);

  // Unnamed nested objects and unnamed <ref>s (resolved) whose element is `tag` (a shape's <bsdf> and
  // <emitter>, a sensor's <film>).
  std::vector<const MitsubaElement*> objects(const std::string& tag);
  // At most one such object (nullptr for none); two is an error.
  const MitsubaElement* object(const std::string& tag);

  // Refuses every property or object not read: "unsupported property "x" (<bsdf type="diffuse"> supports:
  // reflectance)".
  void finish(const std::vector<std::string>& supported) const;

 private:
  struct Child {
    const MitsubaElement* element;  // as written (a <ref> stays a <ref>)
    const MitsubaElement* target;   // what it gives: the element itself or the one a <ref> names
    bool used = false;
  };
  Child* find(const std::string& name);
  const MitsubaElement& typed(const std::string& name, std::initializer_list<const char*> tags,
                              const char* kind);

  const MitsubaElement& element_;
  const MitsubaDocument& document_;
  std::string type_;
  std::vector<Child> children_;
};

// The element a <ref id="..."/> names; an error naming the ref when no element has that id.
const MitsubaElement& resolve_ref(const MitsubaElement& ref, const MitsubaDocument& document);

}  // namespace ochre
