#pragma once
// MaterialGraph: a material as parsed from the scene, before compilation. Every input is either
// a constant (written, or the socket's default) or a link to a node output; links are resolved
// to node indices. Internal to the compiler (graph_parser.cpp, graph_compiler.cpp).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "materials/nodes/node_definition.h"

namespace ochre {

struct OutputRef {
  int node = -1;
  int output = 0;
  friend bool operator==(const OutputRef&, const OutputRef&) = default;
};

struct GraphInput {
  bool linked = false;
  NodeValue constant;  // when not linked
  OutputRef link;      // when linked
};

struct GraphNode {
  std::string name;     // as in the scene; "" for a one-node shorthand material
  bool hidden = false;  // made by the parser to feed an input's default_node
  const NodeDefinition* def = nullptr;
  nlohmann::json params = nlohmann::json::object();  // given parameters, defaults filled in
  std::vector<GraphInput> inputs;                    // one per def->inputs
  Prepared prepared;
};

struct MaterialGraph {
  std::string file, material;
  std::vector<GraphNode> nodes;  // the declared nodes first, then hidden ones
  int declared = 0;
  OutputRef output;

  // Throws the GraphError for `parameter` of node `node` (-1: the material itself).
  [[noreturn]] void fail(int node, const std::string& parameter, const std::string& what) const;
  // "'name.output'" of an output, for messages.
  std::string describe(const OutputRef& ref) const;
};

}  // namespace ochre
