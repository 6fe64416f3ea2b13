// The "cube" shape (docs/scene-format.md, "shapes").
#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/shape_type.h"

namespace ochre {

namespace {

Mesh build_cube(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const Vec3 size = f.vec3("size");
  Mesh mesh = f.fields().in_context("size", [&] { return make_cube(size); });
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType cube_shape() {
  return {
      "cube",
      "box centred at the origin, 12 triangles with flat normals outward; each face carries uv over [0,1]^2 "
      "laid out as Mitsuba 3's cube (an image appears on each face as in Mitsuba)",
      {vec3_field("size", {2, 2, 2}, "the edge lengths along x, y and z")},
      true,
      build_cube};
}

}  // namespace ochre
