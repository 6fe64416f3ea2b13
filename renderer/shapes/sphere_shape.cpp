// The "sphere" shape (docs/scene-format.md, "shapes").
#include <fmt/format.h>

#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/util/memory_budget.h"

namespace ochre {

namespace {

Mesh build_sphere(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const auto radius = static_cast<float>(f.number("radius"));
  const auto subdivisions = static_cast<int>(f.integer("subdivisions"));
  check_memory_estimate(sphere_memory_bytes(subdivisions),
                        fmt::format("{}: a sphere of {:.0f} triangles", f.fields().child("subdivisions"),
                                    sphere_triangle_count(subdivisions)));
  const Vec3d center = f.point("center");
  Mesh mesh = f.fields().in_context("", [&] { return make_sphere(radius, subdivisions); });
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world * Transform::translate(center)); });
  return mesh;
}

}  // namespace

ShapeType sphere_shape() {
  return {
      "sphere",
      "triangulated sphere with exact normals, about 4 x subdivisions^2 triangles (150 bytes each with the "
      "BVH: refused beyond the memory limit)",
      {vec3_field("center", {0, 0, 0}, "the centre"),
       positive_number_field("radius", 1.0, 1e30, "the radius"),
       integer_field("subdivisions", 96, 4, 4096, "bands of latitude (twice as many of longitude)")},
      true,
      build_sphere};
}

}  // namespace ochre
