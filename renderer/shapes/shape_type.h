#pragma once
// Shape types (docs/scene-format.md, "shapes"): each type declares its fields (renderer/json/field_spec.h)
// and builds a mesh from them, in one file of its own (renderer/shapes/*_shape.cpp); shape_registry.cpp
// lists them. The loader dispatches through the registry, and a test checks the docs' table of shapes
// against the declarations. Adding a shape: its file, one line in shape_registry.cpp, its row in the docs.

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/geometry/mesh.h"
#include "renderer/geometry/transform.h"
#include "renderer/json/field_spec.h"
#include "renderer/json/type_registry.h"

namespace ochre {

class OiioTextureProvider;

// What a shape type's build function gets: its fields, read through the type's declarations.
struct ShapeContext {
  const DeclaredFields& fields;
  // The shape's "transform" (identity when absent), then the shift to the rendering origin: what a type
  // builds in object space lands in the coordinates the scene renders in (renderer/scene/scene.h).
  const Transform& to_world;
  const std::filesystem::path&
      dir;                        // the folder of the file that holds the shape: its paths are relative to it
  OiioTextureProvider& textures;  // the scene's textures (displacement maps)
  const Vec3d& origin;  // the rendering origin in the scene's coordinates (procedural displacement's world)
  std::vector<std::string>& warnings;  // what the scene loads but a user should know (Scene::warnings)
};

struct ShapeType {
  std::string name;
  std::string geometry;           // what it makes, one sentence for the docs
  std::vector<FieldSpec> fields;  // the type's own fields; every shape also takes common_shape_fields()
  // False for types whose files carry their own uvs and flip them on import ("mesh"): the loader then does
  // not flip the built mesh's uvs again.
  bool loader_flips_uv = true;
  // Builds the mesh in world space (the type applies ctx.to_world). Errors are InputError naming the field.
  Mesh (*build)(const ShapeContext& ctx) = nullptr;

  // The declarations a shape of this type is read through: "type", the type's own fields, the common ones.
  std::vector<const FieldSpec*> declarations() const;
};

// The fields every shape takes: type, material, name, transform, flip_normals, flip_uv_v, polarizer.
const std::vector<FieldSpec>& common_shape_fields();

class ShapeRegistry : public TypeRegistry<ShapeType> {
 public:
  ShapeRegistry() : TypeRegistry("shape") {}
  static const ShapeRegistry& builtin();

  // Also refuses a type whose own fields repeat a common one (std::logic_error).
  void add(ShapeType type);
};

}  // namespace ochre
