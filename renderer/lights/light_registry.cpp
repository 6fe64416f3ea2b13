// The light types ochre ships (docs/scene-format.md, "lights"). Adding a light: write its file (one
// function returning its LightType) and add one line to the list below. (A static library drops object
// files nothing references, so types cannot register themselves through static objects.) Emissive shapes
// are area lights: they are shapes, not light types.

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "renderer/film/film.h"
#include "renderer/lights/light_type.h"

namespace ochre {

LightType environment_light_type();
LightType point_light_type();
LightType spot_light_type();
LightType flame_light_type();
LightType camera_flash_light_type();
LightType directional_light_type();

const LightRegistry& LightRegistry::builtin() {
  static const LightRegistry registry = [] {
    LightRegistry r;
    for (auto make : {environment_light_type, point_light_type, spot_light_type, flame_light_type,
                      camera_flash_light_type, directional_light_type})
      r.add(make());
    return r;
  }();
  return registry;
}

BuiltLight LightType::load(const JsonFields& f, const std::filesystem::path& dir, const Camera& camera,
                           const Vec3d& origin, float scene_radius) const {
  const FieldSpec type_field = string_field("type", true, "the light type");
  const FieldSpec group_field = light_group_field("group");
  std::vector<const FieldSpec*> specs{&type_field};
  for (const FieldSpec& own : fields) specs.push_back(&own);
  specs.push_back(&group_field);
  const DeclaredFields declared(f, specs);
  declared.check_known();
  BuiltLight built = build(LightContext{declared, dir, camera, origin, scene_radius});
  built.light->group = parse_light_group(f, "group");
  return built;
}

FieldSpec light_group_field(const char* name) {
  return string_field(
      name, false,
      "the light group it belongs to: the render writes a layer per group, which ochre relight "
      "recombines (docs/lights.md, \"Light groups\")");
}

std::string parse_light_group(const JsonFields& f, const char* key) {
  if (!f.has(key)) return "";
  const std::string name = f.required_string(key);
  if (!is_light_group_name(name))
    f.fail(key, fmt::format("'{}' is not a group name: 1 to 64 letters, digits, '_' or '-'", name));
  if (name == kOtherLightGroup)
    f.fail(key, fmt::format("'{}' is the group of the emitters that name none; choose another name", name));
  return name;
}

std::optional<Vec3> parse_light_polarizer(const JsonFields& f) {
  if (!f.has("polarizer")) return std::nullopt;
  const JsonFields p(f.require("polarizer"), f.child("polarizer"));
  p.check_known({"axis"});
  const Vec3 axis = p.required_vec3("axis");
  if (!(length(axis) > 0.0f) || !std::isfinite(length(axis)))
    p.fail("axis", "must be a non-zero vector of finite length");
  return normalize(axis);
}

FieldSpec polarizer_field() {
  return object_field(
      "polarizer", "",
      "{\"axis\": [x, y, z]}: an ideal linear polarizer in front of the light (docs/polarization.md)");
}

}  // namespace ochre
