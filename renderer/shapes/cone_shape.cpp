// The "cone" shape (docs/scene-format.md, "shapes"): an open cone or frustum about z, for lamp shades,
// torch heads and other turned objects.
#include <fmt/format.h>

#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/util/memory_budget.h"

namespace ochre {

namespace {

Mesh build_cone(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const auto radius = static_cast<float>(f.number("radius"));
  const auto top_radius = static_cast<float>(f.number("top_radius"));
  const auto height = static_cast<float>(f.number("height"));
  const auto segments = static_cast<int>(f.integer("segments"));
  const double triangles = cone_triangle_count(segments, top_radius == 0.0f);
  check_triangle_estimate(
      triangles, kTessellatedTriangleBytes,
      fmt::format("{}: a cone of {:.0f} triangles", f.fields().child("segments"), triangles));
  Mesh mesh = f.fields().in_context("", [&] { return make_cone(radius, top_radius, height, segments); });
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType cone_shape() {
  return {
      "cone",
      "open cone about z from z = 0 (`radius`) to `height` (`top_radius`; 0: pointed, else a frustum), no "
      "caps; flat along the slant, smooth around; u around (counter-clockwise), v = z / height. 2 x segments "
      "triangles (segments when pointed)",
      {positive_number_field("radius", 1.0, 1e30, "the radius at z = 0"),
       number_field("top_radius", 0.0, 0.0, 1e30, "the radius at z = height"),
       positive_number_field("height", 2.0, 1e30, "the height along z"),
       integer_field("segments", 256, 3, 1 << 20, "quads around the axis")},
      true,
      build_cone};
}

}  // namespace ochre
