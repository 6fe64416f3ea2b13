#include "materials/graph/graph_analysis.h"

#include <algorithm>

namespace ochre {

namespace {

// Depth-first post-order over the links; a link back to a node on the current path is a cycle.
class TopologicalSort {
 public:
  explicit TopologicalSort(const MaterialGraph& g) : g_(g), mark_(g.nodes.size(), kNew) {}

  std::vector<int> run() {
    for (int n = 0; n < static_cast<int>(g_.nodes.size()); ++n)
      if (mark_[n] == kNew) visit(n);
    return order_;
  }

 private:
  enum Mark { kNew, kOnPath, kDone };

  void visit(int n) {
    mark_[n] = kOnPath;
    path_.push_back(n);
    const GraphNode& node = g_.nodes[n];
    for (size_t i = 0; i < node.inputs.size(); ++i) {
      if (!node.inputs[i].linked) continue;
      const int m = node.inputs[i].link.node;
      if (mark_[m] == kOnPath) report_cycle(m, n, node.def->inputs[i].name);
      if (mark_[m] == kNew) visit(m);
    }
    path_.pop_back();
    mark_[n] = kDone;
    order_.push_back(n);
  }

  // path_ = [m, ..., n]: each node reads the next one, and n reads m. Written in data-flow order.
  [[noreturn]] void report_cycle(int m, int n, const std::string& input) const {
    const auto start = std::find(path_.begin(), path_.end(), m);
    std::string text = "'" + g_.nodes[m].name + "'";
    for (auto it = path_.end(); it != start;) text += " -> '" + g_.nodes[*--it].name + "'";
    g_.fail(n, input, "cycle: " + text + " (each node feeds the next)");
  }

  const MaterialGraph& g_;
  std::vector<Mark> mark_;
  std::vector<int> path_;
  std::vector<int> order_;
};

bool can_convert(SocketType from, SocketType to, bool polymorphic_socket) {
  if (converts_implicitly(from, to)) return true;
  // Math nodes broadcast a float operand to a vector.
  return polymorphic_socket && from == SocketType::kFloat && to == SocketType::kVector;
}

std::string mismatch_hint(SocketType from, SocketType to) {
  if (from == SocketType::kClosure)
    return " (a closure only goes into closure inputs: add, mix, multiply, output)";
  if (to == SocketType::kClosure) return " (only closure nodes such as lambert give closures)";
  if ((from == SocketType::kVector) != (to == SocketType::kVector))
    return " (vectors and colours do not convert)";
  if (from == SocketType::kSpectrum) return " (a spectrum does not convert back to a colour or float)";
  if (from == SocketType::kColour && to == SocketType::kFloat)
    return " (use the texture's value output for a float)";
  return "";
}

TypeResolution static_types(const NodeDefinition& def) {
  TypeResolution t;
  for (const SocketDef& s : def.inputs) t.inputs.push_back(s.type);
  for (const OutputDef& o : def.outputs) t.outputs.push_back(o.type);
  return t;
}

void resolve_node_types(const MaterialGraph& g, int n, GraphTyping& typing) {
  const GraphNode& node = g.nodes[n];
  std::vector<SocketType>& connected = typing.connected[n];
  for (const GraphInput& in : node.inputs)
    connected.push_back(in.linked ? typing.types[in.link.node].outputs[in.link.output] : in.constant.type);

  TypeResolution types = static_types(*node.def);
  if (node.def->resolve_types) {
    try {
      types = node.def->resolve_types(connected);
    } catch (const NodeError& e) {
      g.fail(n, e.parameter(), e.what());
    }
  }
  for (size_t o = 0; o < types.outputs.size(); ++o)
    if (node.prepared.constant_outputs[o]) types.outputs[o] = node.prepared.constant_outputs[o]->type;

  for (size_t i = 0; i < node.inputs.size(); ++i) {
    const SocketType from = connected[i], to = types.inputs[i];
    if (can_convert(from, to, node.def->inputs[i].polymorphic)) continue;
    const GraphInput& in = node.inputs[i];
    const std::string what = in.linked ? g.describe(in.link) : "the constant " + in.constant.describe();
    g.fail(n, node.def->inputs[i].name,
           "type mismatch: " + what + " is a " + to_string(from) + ", this input takes a " + to_string(to) +
               mismatch_hint(from, to));
  }
  typing.types[n] = std::move(types);
}

// Roles flow from the sockets that use a result back to the node producing it, through
// kInherit sockets (math nodes). Processed consumers-first.
void resolve_roles(const MaterialGraph& g, GraphTyping& typing) {
  const size_t count = g.nodes.size();
  std::vector<bool> reflectance(count, false), illuminant(count, false);
  for (auto it = typing.order.rbegin(); it != typing.order.rend(); ++it) {
    const int c = *it;
    const GraphNode& consumer = g.nodes[c];
    for (size_t i = 0; i < consumer.inputs.size(); ++i) {
      if (!consumer.inputs[i].linked) continue;
      const int producer = consumer.inputs[i].link.node;
      switch (consumer.def->inputs[i].role) {
        case SpectralRole::kReflectance:
          reflectance[producer] = true;
          break;
        case SpectralRole::kIlluminant:
          illuminant[producer] = true;
          break;
        case SpectralRole::kInherit:
          reflectance[producer] = reflectance[producer] || reflectance[c];
          illuminant[producer] = illuminant[producer] || illuminant[c];
          break;
        case SpectralRole::kNone:
          break;
      }
    }
  }
  typing.conversion_role.resize(count);
  for (size_t n = 0; n < count; ++n) {
    if (g.nodes[n].def->colour_operands_are_tints || !illuminant[n])
      typing.conversion_role[n] = SpectralRole::kReflectance;
    else
      typing.conversion_role[n] = reflectance[n] ? SpectralRole::kNone : SpectralRole::kIlluminant;
  }
}

void check_output(const MaterialGraph& g, const GraphTyping& typing) {
  const SocketType t = typing.types[g.output.node].outputs[g.output.output];
  if (t == SocketType::kClosure) return;
  const GraphNode& node = g.nodes[g.output.node];
  if (node.name.empty())
    g.fail(-1, "type",
           "a " + node.def->name + " node gives a " + to_string(t) +
               "; a one-node material must be a closure node (lambert, emission, ...)");
  g.fail(-1, "output",
         g.describe(g.output) + " is a " + to_string(t) + "; a material's output must be a closure");
}

}  // namespace

GraphTyping analyse_graph(const MaterialGraph& graph) {
  GraphTyping typing;
  typing.order = TopologicalSort(graph).run();
  typing.types.resize(graph.nodes.size());
  typing.connected.resize(graph.nodes.size());
  for (int n : typing.order) resolve_node_types(graph, n, typing);
  check_output(graph, typing);
  resolve_roles(graph, typing);
  return typing;
}

}  // namespace ochre
