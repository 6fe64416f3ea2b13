// constant(value): a float, colour or vector written once and used by several nodes. Always
// folded away: its consumers read the value directly.

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/json_literal.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

Prepared prepare_constant(const PrepareArgs& args) {
  Prepared p;
  p.constant_outputs = {literal_value(args.params.at("value"))};  // the parser checked the form
  return p;
}

}  // namespace

NodeDefinition constant_node() {
  NodeDefinition d;
  d.name = "constant";
  d.doc = "A constant float, colour or vector.";
  d.params = {required_value_param(
      "value", "a number (float), [r, g, b] (colour, linear Rec.709) or {\"vector\": [x, y, z]}")};
  d.outputs = {{"value", SocketType::kFloat, true, "the value, of the type written"}};
  d.prepare = prepare_constant;
  return d;
}

}  // namespace ochre
