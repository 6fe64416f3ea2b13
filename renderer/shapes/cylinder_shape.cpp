// The "cylinder" shape (docs/scene-format.md, "shapes"): the smooth surface that carries the analytic
// groove materials beside the explicit grooved cylinder.
#include <fmt/format.h>

#include "renderer/shapes/groove_shapes.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/util/memory_budget.h"

namespace ochre {

namespace {

Mesh build_cylinder(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const auto radius = static_cast<float>(f.number("radius"));
  const auto height = static_cast<float>(f.number("height"));
  const auto segments = static_cast<int>(f.integer("segments"));
  const double triangles = cylinder_triangle_count(segments);
  check_triangle_estimate(
      triangles, kTessellatedTriangleBytes,
      fmt::format("{}: a cylinder of {:.0f} triangles", f.fields().child("segments"), triangles));
  Mesh mesh = make_cylinder(radius, height, segments);
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType cylinder_shape() {
  return {"cylinder",
          "open tube about z from z = 0 to `height`, smooth normals; u around (counter-clockwise), v = z / "
          "height. 2 x segments triangles",
          {positive_number_field("radius", 1.0, 1e30, "the radius"),
           positive_number_field("height", 2.0, 1e30, "the height along z"),
           integer_field("segments", 256, 3, 1 << 20, "quads around the axis")},
          true,
          build_cylinder};
}

}  // namespace ochre
