#pragma once
// TypeRegistry: the types of one kind of scene object (shapes, lights) by name, in registration order; a
// type is a struct with a `name` and the declarations of its fields (renderer/json/field_spec.h).
// ShapeRegistry (renderer/shapes/shape_type.h) and LightRegistry (renderer/lights/light_type.h) are its
// two uses.

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "renderer/json/json_fields.h"

namespace ochre {

template <class Type>
class TypeRegistry {
 public:
  // `kind` names the objects in messages ("shape"); `hint` follows the list of known types in the message
  // for an unknown one.
  explicit TypeRegistry(std::string kind, std::string hint = "")
      : kind_(std::move(kind)), hint_(std::move(hint)) {}

  // Throws std::logic_error for a name registered before.
  void add(Type type) {
    if (find(type.name)) throw std::logic_error(kind_ + " type '" + type.name + "' registered twice");
    types_.push_back(std::move(type));
  }
  const Type* find(std::string_view name) const {
    for (const Type& t : types_)
      if (t.name == name) return &t;
    return nullptr;
  }
  // The type `f` names in its "type"; an unknown type is an InputError naming the field and the known ones.
  const Type& type_of(const JsonFields& f) const {
    const std::string type = f.required_string("type");
    const Type* found = find(type);
    if (!found)
      f.fail("type", fmt::format("unknown {} type '{}' (known: {}{})", kind_, type, names(), hint_));
    return *found;
  }
  const std::vector<Type>& types() const { return types_; }
  // The names in registration order: "mesh, sphere, ...".
  std::string names() const {
    std::string list;
    for (const Type& t : types_) list += (list.empty() ? "" : ", ") + t.name;
    return list;
  }

 private:
  std::string kind_, hint_;
  std::vector<Type> types_;
};

}  // namespace ochre
