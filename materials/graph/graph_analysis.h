#pragma once
// Compiler passes over a parsed MaterialGraph that need no values: evaluation order (with cycle
// detection), type resolution and checking, and the spectral role of each node's result.

#include <vector>

#include "materials/graph/material_graph.h"

namespace ochre {

struct GraphTyping {
  std::vector<int> order;                          // every node after the nodes it reads
  std::vector<TypeResolution> types;               // per node
  std::vector<std::vector<SocketType>> connected;  // per node and input: the type connected
  // Per node: the role a colour converted to spectrum at this node takes (kReflectance or
  // kIlluminant); kNone when the node's consumers disagree (an error if a conversion happens).
  std::vector<SpectralRole> conversion_role;
};

// Throws GraphError for a cycle (naming its nodes), a type mismatch, or a polymorphic node that
// cannot combine its inputs.
GraphTyping analyse_graph(const MaterialGraph& graph);

}  // namespace ochre
