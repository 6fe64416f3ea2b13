// Nodes that read the shading point: vertex_colour, uv and position.

#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

void eval_vertex_colour(const NodeArgs& a) {
  a.set_colour(0, a.ctx.vertex_colour);
}
void eval_uv(const NodeArgs& a) {
  a.set_vector(0, {a.ctx.uv.x, a.ctx.uv.y, 0.0f});
}
void eval_position(const NodeArgs& a) {
  a.set_vector(0, a.ctx.p);
}

}  // namespace

NodeDefinition vertex_colour_node() {
  NodeDefinition d;
  d.name = "vertex_colour";
  d.doc = "The mesh's vertex colour, interpolated; (1, 1, 1) when the mesh has none.";
  d.outputs = {{"color", SocketType::kColour, false, "linear Rec.709 colour"}};
  d.context_usage = kUsesVertexColour;
  d.eval = eval_vertex_colour;
  return d;
}

NodeDefinition uv_node() {
  NodeDefinition d;
  d.name = "uv";
  d.doc = "The mesh's texture coordinates as a vector (u, v, 0); (0, 0, 0) when the mesh has none.";
  d.outputs = {{"uv", SocketType::kVector, false, "(u, v, 0)"}};
  d.context_usage = kUsesUV;
  d.eval = eval_uv;
  return d;
}

NodeDefinition position_node() {
  NodeDefinition d;
  d.name = "position";
  d.doc = "The shading point's world position (scene units).";
  d.outputs = {{"position", SocketType::kVector, false, "(x, y, z) in world space"}};
  d.context_usage = kUsesGeometry;
  d.eval = eval_position;
  return d;
}

}  // namespace ochre
