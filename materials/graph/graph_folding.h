#pragma once
// Constant folding: every input becomes an Operand (a constant already converted to the type the
// node reads, or a run-time value with its conversion), and nodes whose results are known at
// compile time are replaced by them. Constants are validated here against their sockets (NaN,
// infinity, ranges), after folding, so a folded negative albedo is caught too.

#include <vector>

#include "materials/graph/graph_analysis.h"

namespace ochre {

struct Operand {
  bool constant = false;
  NodeValue value;                                 // constant: of type `type`
  OutputRef source;                                // run time: the producing output
  SocketType source_type = SocketType::kFloat;     // run time: the type produced
  SocketType type = SocketType::kFloat;            // the type the consumer reads
  SpectralRole role = SpectralRole::kReflectance;  // colour -> spectrum upsampling when converting
};

struct FoldedGraph {
  std::vector<std::vector<Operand>> inputs;   // per node and input
  std::vector<std::vector<Operand>> outputs;  // per node and output: its value, constant or not
  std::vector<bool> runtime;                  // the node must run (when live)
};

FoldedGraph fold_constants(const MaterialGraph& graph, const GraphTyping& typing);

// The run-time function of a node with these resolved types.
NodeFn runtime_function(const NodeDefinition& def, const TypeResolution& types);

}  // namespace ochre
