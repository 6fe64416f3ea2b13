// The shape types ochre ships (docs/scene-format.md, "shapes"). Adding a shape: write its file (one
// function returning its ShapeType) and add one line to the list below. (A static library drops object
// files nothing references, so types cannot register themselves through static objects.)

#include <stdexcept>

#include "renderer/lights/light_type.h"
#include "renderer/shapes/shape_type.h"

namespace ochre {

ShapeType mesh_shape();
ShapeType sphere_shape();
ShapeType plane_shape();
ShapeType disk_shape();
ShapeType cube_shape();
ShapeType groove_plate_shape();
ShapeType cylinder_shape();
ShapeType grooved_cylinder_shape();
ShapeType cone_shape();

const ShapeRegistry& ShapeRegistry::builtin() {
  static const ShapeRegistry registry = [] {
    ShapeRegistry r;
    for (auto make : {mesh_shape, sphere_shape, plane_shape, disk_shape, cube_shape, groove_plate_shape,
                      cylinder_shape, grooved_cylinder_shape, cone_shape})
      r.add(make());
    return r;
  }();
  return registry;
}

const std::vector<FieldSpec>& common_shape_fields() {
  static const std::vector<FieldSpec> fields = {
      string_field("type", true, "the shape type"),
      string_field("material", false, "a material of the scene (required unless a mesh gives \"materials\")"),
      string_field("name", false, "the shape's name in messages and statistics (default: its type)"),
      object_field("transform", "", "object to world (docs/scene-format.md, \"Transforms\")"),
      boolean_field("flip_normals", false, "turn the surface the other way (winding and normals reversed)"),
      boolean_field("flip_uv_v", false, "v -> 1 - v"),
      object_field("polarizer", "",
                   "{\"axis\": [x, y, z]}: a linear polarizer in front of an emissive shape"),
      light_group_field("light_group"),
  };
  return fields;
}

void ShapeRegistry::add(ShapeType type) {
  for (const FieldSpec& own : type.fields)
    for (const FieldSpec& common : common_shape_fields())
      if (own.name == common.name)
        throw std::logic_error("shape type '" + type.name + "' redeclares the common field " + own.name);
  TypeRegistry::add(std::move(type));
}

std::vector<const FieldSpec*> ShapeType::declarations() const {
  const std::vector<FieldSpec>& common = common_shape_fields();
  std::vector<const FieldSpec*> specs{&common.front()};
  for (const FieldSpec& own : fields) specs.push_back(&own);
  for (size_t i = 1; i < common.size(); ++i) specs.push_back(&common[i]);
  return specs;
}

}  // namespace ochre
