#include "renderer/loader/mitsuba/mitsuba_object.h"

#include <fmt/format.h>

#include <algorithm>

namespace ochre {

namespace {

// Elements that hold one value under a name (every other tag is a nested object or a <ref>).
bool is_property_tag(const std::string& tag) {
  static const char* const kTags[] = {"float",    "integer", "boolean", "string",   "rgb",
                                      "spectrum", "point",   "vector",  "transform"};
  return std::any_of(std::begin(kTags), std::end(kTags), [&](const char* t) { return tag == t; });
}

}  // namespace

const MitsubaElement& resolve_ref(const MitsubaElement& ref, const MitsubaDocument& document) {
  for (const auto& [key, value] : ref.attributes)
    if (key != "id" && key != "name")
      fail_at(ref, fmt::format("unexpected attribute \"{}\" (<ref> takes: id, name)", key));
  const std::string* id = ref.attribute("id");
  if (!id) fail_at(ref, "missing attribute \"id\"");
  const auto it = document.ids.find(*id);
  if (it == document.ids.end()) fail_at(ref, fmt::format("no element has id \"{}\"", *id));
  return *it->second;
}

MitsubaObject::MitsubaObject(const MitsubaElement& element, const MitsubaDocument& document)
    : element_(element), document_(document) {
  if (const std::string* type = element.attribute("type")) type_ = *type;
  for (const auto& [key, value] : element.attributes)
    if (key != "type" && key != "id" && key != "name" && !(element.tag == "scene" && key == "version"))
      fail_at(element,
              fmt::format("unexpected attribute \"{}\" (<{}> takes: type, id, name)", key, element.tag));
  if (type_.empty() && element.tag != "scene") fail_at(element, "missing attribute \"type\"");
  for (const MitsubaElement& child : element.children) {
    const MitsubaElement* target = child.tag == "ref" ? &resolve_ref(child, document) : &child;
    if (is_property_tag(child.tag) && child.name().empty())
      fail_at(child, fmt::format("missing attribute \"name\" (a <{}> is a named property)", child.tag));
    const std::string name = child.name();
    if (!name.empty())
      for (const Child& other : children_)
        if (other.element->name() == name)
          fail_at(child, fmt::format("property \"{}\" is given twice (first at line {})", name,
                                     other.element->line));
    children_.push_back({&child, target, false});
  }
}

MitsubaObject::Child* MitsubaObject::find(const std::string& name) {
  for (Child& c : children_)
    if (c.element->name() == name) return &c;
  return nullptr;
}

bool MitsubaObject::has(const std::string& name) const {
  return std::any_of(children_.begin(), children_.end(),
                     [&](const Child& c) { return c.element->name() == name; });
}

const MitsubaElement* MitsubaObject::get(const std::string& name) {
  Child* c = find(name);
  if (!c) return nullptr;
  c->used = true;
  return c->target;
}

const MitsubaElement& MitsubaObject::typed(const std::string& name, std::initializer_list<const char*> tags,
                                           const char* kind) {
  const MitsubaElement* e = get(name);
  if (!std::any_of(tags.begin(), tags.end(), [&](const char* t) { return e->tag == t; }))
    fail_at(*e,
            fmt::format("property \"{}\" of <{} type=\"{}\"> must be {}", name, element_.tag, type_, kind));
  return *e;
}

std::optional<double> MitsubaObject::number(const std::string& name) {
  if (!has(name)) return std::nullopt;
  return number_value(typed(name, {"float", "integer"}, "a number (<float> or <integer>)"));
}

std::optional<long long> MitsubaObject::integer(const std::string& name) {
  if (!has(name)) return std::nullopt;
  const MitsubaElement& e = typed(name, {"integer"}, "an <integer>");
  const double v = number_value(e);
  if (std::abs(v) > 9.0e15) fail_at(e, "value: the integer is too large");
  return static_cast<long long>(v);
}

bool MitsubaObject::boolean(const std::string& name, bool fallback) {
  if (!has(name)) return fallback;
  const MitsubaElement& e = typed(name, {"boolean"}, "a <boolean>");
  const std::string* value = e.attribute("value");
  if (!value) fail_at(e, "missing attribute \"value\"");
  std::string lower = *value;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "true") return true;
  if (lower == "false") return false;
  fail_at(e, fmt::format("value: \"{}\" is not true or false", *value));
}

std::optional<std::string> MitsubaObject::string(const std::string& name) {
  if (!has(name)) return std::nullopt;
  const MitsubaElement& e = typed(name, {"string"}, "a <string>");
  const std::string* value = e.attribute("value");
  if (!value) fail_at(e, "missing attribute \"value\"");
  return *value;
}

std::string MitsubaObject::required_string(const std::string& name) {
  const std::optional<std::string> value = string(name);
  if (!value)
    fail(
        fmt::format("<{} type=\"{}\"> needs <string name=\"{}\" value=\"...\"/>", element_.tag, type_, name));
  return *value;
}

std::optional<Vec3d> MitsubaObject::point(const std::string& name) {
  if (!has(name)) return std::nullopt;
  return vector_value(typed(name, {"point", "vector"}, "a <point> or <vector>"));
}

std::optional<Matrix4d> MitsubaObject::transform(const std::string& name) {
  if (!has(name)) return std::nullopt;
  return transform_value(typed(name, {"transform"}, "a <transform>"));
}

std::optional<nlohmann::json> MitsubaObject::colour(const std::string& name, MitsubaColourRole role) {
  if (!has(name)) return std::nullopt;
  return colour_value(document_, typed(name, {"float", "rgb", "spectrum"}, "a <float>, <rgb> or <spectrum>"),
                      role);
}

std::vector<const MitsubaElement*> MitsubaObject::objects(const std::string& tag) {
  std::vector<const MitsubaElement*> found;
  for (Child& c : children_)
    if (c.element->name().empty() && c.target->tag == tag) {
      c.used = true;
      found.push_back(c.target);
    }
  return found;
}

const MitsubaElement* MitsubaObject::object(const std::string& tag) {
  const std::vector<const MitsubaElement*> found = objects(tag);
  if (found.size() > 1)
    fail_at(*found[1], fmt::format("<{} type=\"{}\"> takes one <{}> (the first is at line {})", element_.tag,
                                   type_, tag, found[0]->line));
  return found.empty() ? nullptr : found.front();
}

void MitsubaObject::finish(const std::vector<std::string>& supported) const {
  for (const Child& c : children_) {
    if (c.used) continue;
    std::string list;
    for (const std::string& s : supported) list += (list.empty() ? "" : ", ") + s;
    const std::string what = c.element->name().empty() ? fmt::format("<{}> inside <{} type=\"{}\">",
                                                                     c.target->tag, element_.tag, type_)
                                                       : fmt::format("property \"{}\"", c.element->name());
    fail_at(*c.element, fmt::format("unsupported {} (ochre reads these of <{} type=\"{}\">: {})", what,
                                    element_.tag, type_, list.empty() ? "none" : list));
  }
}

}  // namespace ochre
