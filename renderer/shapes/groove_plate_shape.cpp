// The "groove_plate" shape (docs/scene-format.md, "shapes"): explicit V-grooves to compare with the
// analytic groove materials (docs/materials/vgroove.md).
#include <fmt/format.h>

#include "renderer/shapes/groove_shapes.h"
#include "renderer/shapes/shape_type.h"
#include "renderer/util/memory_budget.h"

namespace ochre {

namespace {

Mesh build_groove_plate(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  GroovePlate plate;
  plate.alpha_degrees = static_cast<float>(f.number("alpha"));
  plate.pitch = static_cast<float>(f.number("pitch"));
  plate.count = static_cast<int>(f.integer("count"));
  plate.length = static_cast<float>(f.number("length"));
  plate.tile_pitches = static_cast<float>(f.number("tile"));
  const double triangles = groove_plate_triangle_count(plate);
  const std::string where = f.fields().child("count");
  check_triangle_estimate(
      triangles, kTessellatedTriangleBytes,
      groove_plate_tiles(plate) > 1
          ? fmt::format("{}: a groove plate of {:.0f} triangles ({} grooves x {:.0f} tiles along them)",
                        where, triangles, plate.count, groove_plate_tiles(plate))
          : fmt::format("{}: a groove plate of {:.0f} triangles", where, triangles));
  Mesh mesh = make_groove_plate(plate);
  mesh.transform(Transform::rotate(static_cast<float>(f.number("orientation")), {0, 0, 1}));
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType groove_plate_shape() {
  return {
      "groove_plate",
      "`count` parallel V-grooves of dihedral angle `alpha` and width `pitch`, `length` long, along x turned "
      "by `orientation` degrees about z; ridges at z = 0, valleys below; flat facets, cut along the grooves "
      "into tiles at most `tile` pitches long; u along the grooves. 4 x count x ceil(length / (tile x "
      "pitch)) triangles",
      {number_field("alpha", 90.0, 0.1, 179.9, "the dihedral angle in degrees"),
       positive_number_field("pitch", 1.0, 1e30, "the width of a groove"),
       integer_field("count", 40, 1, 1 << 22, "the number of grooves"),
       positive_number_field("length", 40.0, 1e30, "the length along the grooves"),
       number_field("tile", 8.0, 0.0, 1e30, "the longest facet piece, in pitches (0: one strip per facet)"),
       number_field("orientation", 0.0, -360.0, 360.0, "degrees about z")},
      true,
      build_groove_plate};
}

}  // namespace ochre
