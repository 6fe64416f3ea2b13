#pragma once
// NodeRegistry: the node types a material may use, by name. builtin() holds every node ochre
// ships (builtin_nodes.cpp lists them); tests may build their own registry with extra nodes.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "materials/nodes/node_definition.h"

namespace ochre {

class NodeRegistry {
 public:
  static const NodeRegistry& builtin();

  // Adds a definition; throws std::logic_error for a duplicate or inconsistent definition.
  void add(NodeDefinition definition);
  const NodeDefinition* find(std::string_view name) const;
  // Node type names in alphabetical order.
  std::vector<std::string> names() const;
  const std::vector<std::unique_ptr<const NodeDefinition>>& definitions() const { return definitions_; }

 private:
  std::vector<std::unique_ptr<const NodeDefinition>> definitions_;
};

}  // namespace ochre
