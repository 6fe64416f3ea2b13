#include "materials/graph/graph_parser.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "materials/core/single_precision.h"
#include "materials/nodes/json_literal.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/resource_resolver.h"
#include "materials/nodes/spectrum_source.h"

namespace ochre {

namespace {

using nlohmann::json;

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out.empty() ? "none" : out;
}

class Parser {
 public:
  Parser(MaterialGraph& graph, ResourceResolver& resolver, const NodeRegistry& registry)
      : g_(graph), resolver_(resolver), registry_(registry) {}

  void parse(const json& material) {
    if (!material.is_object())
      g_.fail(-1, "", "a material must be a JSON object, got " + json_excerpt(material));
    if (material.contains("nodes"))
      parse_graph(material);
    else if (material.contains("type"))
      parse_shorthand(material);
    else
      g_.fail(-1, "", "a material needs \"type\" (one node) or \"nodes\" and \"output\" (a graph)");
  }

 private:
  void parse_graph(const json& material) {
    for (const auto& [key, value] : material.items())
      if (key != "nodes" && key != "output")
        g_.fail(-1, key, "unknown key (a graph material has \"nodes\" and \"output\")");
    const json& nodes = material.at("nodes");
    if (!nodes.is_object() || nodes.empty())
      g_.fail(-1, "nodes", "\"nodes\" must be a non-empty JSON object");
    for (const auto& [name, body] : nodes.items()) declare_node(name, body);
    g_.declared = static_cast<int>(g_.nodes.size());
    int index = 0;
    for (const auto& [name, body] : nodes.items()) parse_node_body(index++, body);

    if (!material.contains("output"))
      g_.fail(-1, "output", "missing: name the node whose closure is the material");
    const json& output = material.at("output");
    if (!output.is_string())
      g_.fail(-1, "output", "must be a node name (string), got " + json_excerpt(output));
    g_.output = parse_link(-1, "output", output.get<std::string>());
  }

  void parse_shorthand(const json& material) {
    declare_node("", material);
    g_.declared = 1;
    parse_node_body(0, material);
    g_.output = {0, 0};
  }

  void declare_node(const std::string& name, const json& body) {
    const int index = static_cast<int>(g_.nodes.size());
    g_.nodes.push_back({});
    g_.nodes.back().name = name;
    if (!body.is_object()) g_.fail(index, "", "a node must be a JSON object, got " + json_excerpt(body));
    if (name.find('.') != std::string::npos) g_.fail(index, "", "node names cannot contain '.'");
    if (!body.contains("type"))
      g_.fail(index, "type", "missing node type (known: " + join(registry_.names()) + ")");
    const json& type = body.at("type");
    if (!type.is_string()) g_.fail(index, "type", "must be a string, got " + json_excerpt(type));
    const NodeDefinition* def = registry_.find(type.get<std::string>());
    if (!def)
      g_.fail(index, "type",
              "unknown node type '" + type.get<std::string>() + "' (known: " + join(registry_.names()) + ")");
    g_.nodes.back().def = def;
    g_.nodes.back().inputs.resize(def->inputs.size());
    by_name_[name] = index;
  }

  void parse_node_body(int index, const json& body) {
    const NodeDefinition& def = *g_.nodes[index].def;
    std::vector<bool> given(def.inputs.size(), false);
    for (const auto& [key, value] : body.items()) {
      if (key == "type") continue;
      if (const int i = def.input_index(key); i >= 0) {
        g_.nodes[index].inputs[i] = parse_input(index, key, value);
        given[i] = true;
      } else if (const ParamDef* p = def.param(key)) {
        g_.nodes[index].params[key] = parse_param(index, *p, value);
      } else {
        g_.fail(index, key,
                "unknown parameter of a " + def.name + " node (it takes: " + parameter_list(def) + ")");
      }
    }
    for (const ParamDef& p : def.params) {
      if (g_.nodes[index].params.contains(p.name)) continue;
      if (p.required) g_.fail(index, p.name, "missing required parameter");
      if (!p.default_value.is_null()) g_.nodes[index].params[p.name] = p.default_value;
    }
    for (size_t i = 0; i < def.inputs.size(); ++i)
      if (!given[i]) g_.nodes[index].inputs[i] = default_input(def.inputs[i]);
    prepare(index);
  }

  static std::string parameter_list(const NodeDefinition& def) {
    std::vector<std::string> names;
    for (const SocketDef& s : def.inputs) names.push_back(s.name);
    for (const ParamDef& p : def.params) names.push_back(p.name);
    return join(names);
  }

  GraphInput default_input(const SocketDef& socket) {
    GraphInput in;
    if (socket.default_node.empty()) {
      in.constant = socket.default_value;
      return in;
    }
    in.linked = true;
    in.link = {hidden_node(socket.default_node), 0};
    return in;
  }

  // One shared hidden node per type (e.g. the mesh uv feeding every texture without a uv input).
  int hidden_node(const std::string& type) {
    if (auto it = hidden_.find(type); it != hidden_.end()) return it->second;
    const NodeDefinition* def = registry_.find(type);
    if (!def) throw std::logic_error("default node type '" + type + "' is not registered");
    GraphNode node;
    node.name = "(default " + type + ")";
    node.hidden = true;
    node.def = def;
    node.inputs.resize(def->inputs.size());
    g_.nodes.push_back(std::move(node));
    const int index = static_cast<int>(g_.nodes.size()) - 1;
    for (size_t i = 0; i < def->inputs.size(); ++i) g_.nodes[index].inputs[i] = default_input(def->inputs[i]);
    prepare(index);
    hidden_[type] = index;
    return index;
  }

  GraphInput parse_input(int node, const std::string& socket, const json& j) {
    GraphInput in;
    if (j.is_object() && j.contains("link")) {
      if (j.size() != 1 || !j.at("link").is_string())
        g_.fail(node, socket, "a link is written {\"link\": \"node\"} or {\"link\": \"node.output\"}");
      in.linked = true;
      in.link = parse_link(node, socket, j.at("link").get<std::string>());
      return in;
    }
    if (is_spectrum_object(j)) {
      in.constant = spectrum_literal(node, socket, j);
      return in;
    }
    std::optional<NodeValue> literal;
    try {
      literal = literal_value(j);
    } catch (const std::invalid_argument& e) {
      g_.fail(node, socket, e.what());
    }
    if (!literal)
      g_.fail(node, socket,
              "expected a number, [r, g, b], {\"vector\": [x, y, z]}, a spectrum {\"name\": ...}, "
              "{\"file\": ...}, {\"wavelengths\": [...], \"values\": [...]} or {\"blackbody\": ...}, "
              "or {\"link\": \"node[.output]\"}; got " +
                  json_excerpt(j));
    in.constant = *literal;
    return in;
  }

  NodeValue spectrum_literal(int node, const std::string& socket, const json& j) {
    try {
      return NodeValue::of_spectrum(spectrum_from_object(j, resolver_));
    } catch (const SpectrumObjectError& e) {
      g_.fail(node, socket, e.what());
    }
  }

  OutputRef parse_link(int node, const std::string& socket, const std::string& text) {
    const size_t dot = text.find('.');
    const std::string target = text.substr(0, dot);
    const auto it = by_name_.find(target);
    if (target.empty() || it == by_name_.end() || g_.nodes[it->second].name.empty()) {
      std::vector<std::string> names;
      for (int i = 0; i < g_.declared; ++i) names.push_back(g_.nodes[i].name);
      if (g_.declared == 1 && g_.nodes[0].name.empty()) names.clear();
      g_.fail(node, socket, "link to unknown node '" + target + "' (nodes: " + join(names) + ")");
    }
    OutputRef ref{it->second, 0};
    if (dot != std::string::npos) {
      const NodeDefinition& def = *g_.nodes[ref.node].def;
      ref.output = def.output_index(text.substr(dot + 1));
      if (ref.output < 0) {
        std::vector<std::string> outputs;
        for (const OutputDef& o : def.outputs) outputs.push_back(o.name);
        g_.fail(node, socket,
                "node '" + target + "' has no output '" + text.substr(dot + 1) +
                    "' (outputs: " + join(outputs) + ")");
      }
    }
    return ref;
  }

  json parse_param(int node, const ParamDef& p, const json& j) {
    switch (p.kind) {
      case ParamKind::kString: {
        if (!j.is_string()) g_.fail(node, p.name, "expected a string, got " + json_excerpt(j));
        const std::string s = j.get<std::string>();
        if (!p.choices.empty() && std::find(p.choices.begin(), p.choices.end(), s) == p.choices.end())
          g_.fail(node, p.name, unknown_choice(p, s));
        return j;
      }
      case ParamKind::kInt: {
        if (!j.is_number() || j.get<double>() != std::floor(j.get<double>()))
          g_.fail(node, p.name, "expected an integer, got " + json_excerpt(j));
        // Range-checked as a double: converting first would wrap (4294967297 -> 1).
        const double x = j.get<double>();
        check_range(node, p, x);
        if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max())
          g_.fail(node, p.name, "value " + json_excerpt(j) + " is outside the range of a 32-bit integer");
        return json(static_cast<int>(x));
      }
      case ParamKind::kFloat: {
        if (!j.is_number()) g_.fail(node, p.name, "expected a finite number, got " + json_excerpt(j));
        if (const std::string problem = single_precision_problem(j.get<double>()); !problem.empty())
          g_.fail(node, p.name, "expected a finite number, got " + json_excerpt(j) + " (" + problem + ")");
        check_range(node, p, j.get<double>());
        return j;
      }
      case ParamKind::kValue:
        try {
          if (literal_value(j)) return j;
        } catch (const std::invalid_argument& e) {
          g_.fail(node, p.name, e.what());
        }
        g_.fail(node, p.name,
                "expected a number, [r, g, b] or {\"vector\": [x, y, z]}, got " + json_excerpt(j));
    }
    return j;
  }

  void check_range(int node, const ParamDef& p, double x) {
    if (p.min && x < *p.min)
      g_.fail(node, p.name, "value " + number_text(x) + " is below the minimum " + number_text(*p.min));
    if (p.max && x > *p.max)
      g_.fail(node, p.name, "value " + number_text(x) + " is above the maximum " + number_text(*p.max));
  }

  void prepare(int index) {
    GraphNode& node = g_.nodes[index];
    if (node.def->prepare) {
      try {
        node.prepared = node.def->prepare(PrepareArgs{node.params, resolver_, *node.def});
      } catch (const NodeError& e) {
        g_.fail(index, e.parameter(), e.what());
      } catch (const std::exception& e) {
        g_.fail(index, "", e.what());
      }
    }
    node.prepared.constant_outputs.resize(node.def->outputs.size());
  }

  MaterialGraph& g_;
  ResourceResolver& resolver_;
  const NodeRegistry& registry_;
  std::map<std::string, int> by_name_;
  std::map<std::string, int> hidden_;
};

}  // namespace

MaterialGraph parse_material_graph(const json& material, const std::string& material_name,
                                   const std::string& scene_file, ResourceResolver& resolver,
                                   const NodeRegistry& registry) {
  MaterialGraph graph;
  graph.file = scene_file;
  graph.material = material_name;
  Parser(graph, resolver, registry).parse(material);
  return graph;
}

}  // namespace ochre
