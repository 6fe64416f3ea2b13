// projection(position; origin, u_axis, v_axis, depth): planar projection of a position (by default the
// shading point's world position) into the frame of a slide projector, so that an image can be painted
// onto a surface that has no uvs (a scan) or whose uvs do not suit (a cave's atlas). Outputs the
// texture coordinates, whether the point lies inside the projected frame, and the texture filter width
// in those coordinates (for the texture node's `footprint` input).

#include <cmath>
#include <string>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/json_literal.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

struct ProjectionData {
  Vec3 origin, u_dual, v_dual, normal;  // u = dot(p - origin, u_dual); dual axes handle skewed frames
  float depth = 0;
  float inverse_size = 0;  // 1 / the shorter axis length: world footprint -> uv footprint
};

Vec3 vector_param(const PrepareArgs& args, const char* name) {
  const std::optional<NodeValue> v = literal_value(args.params.at(name));  // the parser checked the form
  if (v && v->type == SocketType::kVector) return v->vector;
  if (v && v->type == SocketType::kColour) return {v->colour.r, v->colour.g, v->colour.b};
  throw NodeError(name,
                  "expected [x, y, z] or {\"vector\": [x, y, z]}, got " + json_excerpt(args.params.at(name)));
}

Prepared prepare_projection(const PrepareArgs& args) {
  auto data = std::make_shared<ProjectionData>();
  data->origin = vector_param(args, "origin");
  const Vec3 u = vector_param(args, "u_axis"), v = vector_param(args, "v_axis");
  const Vec3 n = cross(u, v);
  const float area = length(n);
  if (!(area > 0.0f) || !std::isfinite(area))
    throw NodeError("v_axis", "u_axis and v_axis must be non-zero, not parallel, and of finite length");
  data->normal = n / area;
  // Dual basis within the plane: dot(u_dual, u) = 1, dot(u_dual, v) = 0 (and likewise for v_dual).
  data->u_dual = cross(v, data->normal) / area;
  data->v_dual = cross(data->normal, u) / area;
  data->depth = args.params.at("depth").get<float>();
  data->inverse_size = 1.0f / std::fmin(length(u), length(v));
  Prepared p;
  p.payload = data;
  return p;
}

void eval_projection(const NodeArgs& a) {
  const ProjectionData& d = a.data<ProjectionData>();
  const Vec3 offset = a.in_vector(0) - d.origin;
  const float u = dot(offset, d.u_dual), v = dot(offset, d.v_dual);
  if (a.output_used(0)) a.set_vector(0, {u, v, 0.0f});
  if (a.output_used(1)) {
    const bool inside =
        u >= 0.0f && u <= 1.0f && v >= 0.0f && v <= 1.0f && std::fabs(dot(offset, d.normal)) <= d.depth;
    a.set_float(1, inside ? 1.0f : 0.0f);
  }
  if (a.output_used(2)) a.set_float(2, a.ctx.footprint * d.inverse_size);
}

}  // namespace

NodeDefinition projection_node() {
  NodeDefinition d;
  d.name = "projection";
  d.doc = "Planar projection of a position into a projector frame: uv, inside-the-frame mask, footprint.";
  d.inputs = {context_input("position", SocketType::kVector, "position",
                            "the point projected; default: the shading point's world position")};
  d.params = {required_value_param("origin", "world position of the frame's corner uv = (0, 0)"),
              required_value_param("u_axis", "world vector from uv (0, 0) to (1, 0): the frame's width"),
              required_value_param("v_axis", "world vector from uv (0, 0) to (0, 1): the frame's height"),
              number_param("depth", 1e30, 0.0, 3.4e38,
                           "points farther than this from the projector plane (either side) are outside")};
  d.outputs = {{"uv", SocketType::kVector, false, "(u, v, 0) in the frame"},
               {"inside", SocketType::kFloat, false, "1 inside the frame and the depth range, else 0"},
               {"footprint", SocketType::kFloat, false, "texture filter width in frame uv units"}};
  d.context_usage = kUsesGeometry;
  d.prepare = prepare_projection;
  d.eval = eval_projection;
  return d;
}

}  // namespace ochre
