#pragma once
// Scene JSON -> MaterialGraph: checks the material's structure, every node's type, parameters and
// constants, resolves links by name, and runs each node's prepare() (files and textures are
// opened here). Throws GraphError naming file, material, node and parameter.

#include <nlohmann/json.hpp>
#include <string>

#include "materials/graph/material_graph.h"
#include "materials/nodes/node_registry.h"

namespace ochre {

class ResourceResolver;

MaterialGraph parse_material_graph(const nlohmann::json& material, const std::string& material_name,
                                   const std::string& scene_file, ResourceResolver& resolver,
                                   const NodeRegistry& registry);

}  // namespace ochre
