#pragma once
// compile_material: scene JSON of one material -> CompiledMaterial, once per material.
// Passes: parse (graph_parser) -> order, types, roles (graph_analysis) -> constant folding and
// validation (graph_folding) -> dead-node removal, registers, instructions, facts
// (program_builder). The node types and the JSON format are documented in docs/nodes.md.
// Every error is a GraphError naming the scene file, the material, the node and the parameter.

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "materials/graph/compiled_material.h"
#include "materials/graph/graph_error.h"
#include "materials/nodes/resource_resolver.h"
#include "materials/nodes/node_registry.h"

namespace ochre {

std::shared_ptr<const CompiledMaterial> compile_material(const nlohmann::json& material,
                                                         const std::string& material_name,
                                                         const std::string& scene_file,
                                                         ResourceResolver& resolver);

// The same with another set of node types (tests, plug-ins).
std::shared_ptr<const CompiledMaterial> compile_material(const nlohmann::json& material,
                                                         const std::string& material_name,
                                                         const std::string& scene_file,
                                                         ResourceResolver& resolver,
                                                         const NodeRegistry& registry);

}  // namespace ochre
