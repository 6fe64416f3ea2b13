// The "disk" shape (docs/scene-format.md, "shapes").
#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/shape_type.h"

namespace ochre {

namespace {

Mesh build_disk(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const auto radius = static_cast<float>(f.number("radius"));
  const auto segments = static_cast<int>(f.integer("segments"));
  Mesh mesh = f.fields().in_context("", [&] { return make_disk(radius, segments); });
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType disk_shape() {
  return {"disk",
          "in the xy plane, normal +z, a fan of `segments` triangles",
          {positive_number_field("radius", 1.0, 1e30, "the radius"),
           integer_field("segments", 128, 3, 1 << 20, "triangles around the centre")},
          true,
          build_disk};
}

}  // namespace ochre
