// The "plane" shape (docs/scene-format.md, "shapes").
#include "renderer/shapes/procedural_shapes.h"
#include "renderer/shapes/shape_type.h"

namespace ochre {

namespace {

Mesh build_plane(const ShapeContext& ctx) {
  const DeclaredFields& f = ctx.fields;
  const auto [width, height] = f.number_pair("size");
  const Vec2 size{static_cast<float>(width), static_cast<float>(height)};
  Mesh mesh = f.fields().in_context("", [&] { return make_plane(size); });
  f.fields().in_context("", [&] { mesh.transform(ctx.to_world); });
  return mesh;
}

}  // namespace

ShapeType plane_shape() {
  return {"plane",
          "centred in the xy plane, normal +z, uv over [0,1]^2",
          {number_pair_field("size", {2.0, 2.0}, 0.0, kNoMaximum, true, "[width, height]",
                             "width along x and height along y")},
          true,
          build_plane};
}

}  // namespace ochre
