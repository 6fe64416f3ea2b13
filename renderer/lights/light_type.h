#pragma once
// Light types (docs/scene-format.md, "lights"): each type declares its fields (renderer/json/field_spec.h)
// and builds its light from them, in the file of the light itself; light_registry.cpp lists them. The
// loader dispatches through the registry, and a test checks the docs' table of lights against the
// declarations. Adding a light: its file, one line in light_registry.cpp, its row in the docs.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/camera/camera.h"
#include "renderer/json/field_spec.h"
#include "renderer/json/type_registry.h"
#include "renderer/lights/flame_light.h"
#include "renderer/lights/light.h"

namespace ochre {

// What a light type's build function gets: its fields, read through the type's declarations.
struct LightContext {
  const DeclaredFields& fields;
  const std::filesystem::path&
      dir;               // the folder of the file that holds the light: its paths are relative to it
  const Camera& camera;  // lights placed relative to the camera (camera_flash)
  // The rendering origin in the scene's coordinates (renderer/scene/scene.h): a light at position p (read
  // in double precision) is placed at p - origin.
  const Vec3d& origin;
  float scene_radius;  // lights at infinity estimate their power over the scene's bounding sphere

  // The field `key` as a position in the coordinates the scene renders in.
  Vec3 position(const char* key) const { return (fields.point(key) - origin).to_float(); }
};

struct BuiltLight {
  std::unique_ptr<Light> light;
  std::optional<FlameLight> flame;  // a flame flickers in frame sequences; its light is `light`
  // The field a message names when the light's power overflows single precision (a radiance of 3e38 would
  // turn every sample it reaches into infinity); empty: no check.
  std::string power_field;
};

struct LightType {
  std::string name;
  std::string summary;            // what it is, one sentence for the docs
  std::vector<FieldSpec> fields;  // every field but "type"
  bool one_per_scene = false;     // the environment
  BuiltLight (*build)(const LightContext& ctx) = nullptr;

  // Reads `f` (a "lights" entry of this type) through the declarations, refusing unknown keys, and builds
  // the light. `dir`, `camera` and `scene_radius` as in LightContext.
  BuiltLight load(const JsonFields& f, const std::filesystem::path& dir, const Camera& camera,
                  const Vec3d& origin, float scene_radius) const;
};

// "polarizer": {"axis": [x, y, z]} in front of a light or an emissive shape: the world transmission axis
// (renderer/lights/light_polarizer.h); nullopt when absent.
std::optional<Vec3> parse_light_polarizer(const JsonFields& f);
// The declaration of that field.
FieldSpec polarizer_field();
// "group" of a light, "light_group" of an emissive shape: its declaration, and the name (InputError naming
// the field unless it is 1 to 64 letters, digits, '_' or '-', and not the reserved "other"; "" when absent).
FieldSpec light_group_field(const char* name);
std::string parse_light_group(const JsonFields& f, const char* key);

class LightRegistry : public TypeRegistry<LightType> {
 public:
  LightRegistry() : TypeRegistry("light", "; emissive shapes are area lights") {}
  static const LightRegistry& builtin();
};

}  // namespace ochre
