#include "materials/nodes/node_registry.h"

#include <algorithm>
#include <stdexcept>

namespace ochre {

namespace {

// Catches definition mistakes when the registry is built, not when a scene happens to use them.
void check_definition(const NodeDefinition& d) {
  auto fail = [&d](const std::string& what) {
    throw std::logic_error("node definition '" + d.name + "': " + what);
  };
  if (d.name.empty()) fail("empty name");
  if (d.outputs.empty()) fail("no outputs");
  if (d.outputs.size() > 32) fail("more than 32 outputs");
  bool polymorphic_inputs = false;
  for (const SocketDef& s : d.inputs) polymorphic_inputs = polymorphic_inputs || s.polymorphic;
  if (polymorphic_inputs && (!d.resolve_types || !d.select))
    fail("polymorphic inputs need resolve_types and select");
  // A node without a run-time function must make every output constant in prepare() (constant).
  if (!d.eval && !d.select && !d.prepare) fail("no eval function");
  for (const SocketDef& s : d.inputs)
    if (d.param(s.name)) fail("'" + s.name + "' is both an input and a parameter");
  if (d.has_closure_output() && d.outputs.size() != 1) fail("a closure node has exactly one output");
  for (const ParamDef& p : d.params) {
    if (p.choices.empty() || p.default_value.is_null()) continue;
    const auto& c = p.choices;
    if (!p.default_value.is_string() ||
        std::find(c.begin(), c.end(), p.default_value.get<std::string>()) == c.end())
      fail("the default of '" + p.name + "' is not one of its choices");
  }
}

}  // namespace

void NodeRegistry::add(NodeDefinition definition) {
  check_definition(definition);
  if (find(definition.name)) throw std::logic_error("node type '" + definition.name + "' registered twice");
  definitions_.push_back(std::make_unique<const NodeDefinition>(std::move(definition)));
}

const NodeDefinition* NodeRegistry::find(std::string_view name) const {
  for (const auto& d : definitions_)
    if (d->name == name) return d.get();
  return nullptr;
}

std::vector<std::string> NodeRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& d : definitions_) out.push_back(d->name);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ochre
