// The "grooved_cylinder" shape (docs/scene-format.md, "shapes"): a cylinder with circumferential V-grooves,
// so that the groove direction turns around the surface.
#include <fmt/format.h>

#include <cmath>

#include "renderer/shapes/groove_shapes.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/util/memory_budget.h"

namespace ochre {

namespace {

Mesh build_grooved_cylinder(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  GroovedCylinder c;
  c.radius = static_cast<float>(f.number("radius"));
  c.height = static_cast<float>(f.number("height"));
  c.alpha_degrees = static_cast<float>(f.number("alpha"));
  c.pitch = static_cast<float>(f.number("pitch"));
  c.segments = static_cast<int>(f.integer("segments"));
  if (!(c.pitch <= c.height)) f.fail("pitch", "must not exceed the height");
  if (!(0.5 * c.pitch / std::tan(0.5 * c.alpha_degrees * M_PI / 180.0) < c.radius))
    f.fail("alpha", "the grooves would be deeper than the radius: increase alpha or decrease the pitch");
  const double triangles = grooved_cylinder_triangle_count(c);
  check_triangle_estimate(
      triangles, kTessellatedTriangleBytes,
      fmt::format("{}: a grooved cylinder of {:.0f} grooves x {} segments ({:.0f} triangles)",
                  f.fields().where(), groove_count(c), c.segments, triangles));
  Mesh mesh = make_grooved_cylinder(c);
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType grooved_cylinder_shape() {
  return {
      "grooved_cylinder",
      "the cylinder with circumferential V-grooves of width `pitch` along z (ridges at `radius`; the "
      "grooves must be shallower than the radius), as many as fit in `height` (floor(height / pitch)); flat "
      "in the profile, smooth around. 4 x grooves x segments triangles",
      {positive_number_field("radius", 1.0, 1e30, "the radius at the ridges"),
       positive_number_field("height", 2.0, 1e30, "the height along z"),
       number_field("alpha", 90.0, 0.1, 179.9, "the dihedral angle of the grooves in degrees"),
       positive_number_field("pitch", 0.05, 1e30, "the width of a groove along z (at most `height`)"),
       integer_field("segments", 256, 3, 1 << 20, "quads around the axis")},
      true,
      build_grooved_cylinder};
}

}  // namespace ochre
