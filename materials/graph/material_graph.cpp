#include "materials/graph/material_graph.h"

#include "materials/graph/graph_error.h"

namespace ochre {

void MaterialGraph::fail(int node, const std::string& parameter, const std::string& what) const {
  const std::string node_name = node >= 0 ? nodes[node].name : "";
  throw GraphError(file, material, node_name, parameter, what);
}

std::string MaterialGraph::describe(const OutputRef& ref) const {
  const GraphNode& n = nodes[ref.node];
  return "'" + n.name + "." + n.def->outputs[ref.output].name + "'";
}

}  // namespace ochre
