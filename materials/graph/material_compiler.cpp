#include "materials/graph/material_compiler.h"

#include "materials/graph/graph_analysis.h"
#include "materials/graph/graph_folding.h"
#include "materials/graph/graph_parser.h"
#include "materials/graph/program_builder.h"

namespace ochre {

std::shared_ptr<const CompiledMaterial> compile_material(const nlohmann::json& material,
                                                         const std::string& material_name,
                                                         const std::string& scene_file,
                                                         ResourceResolver& resolver) {
  return compile_material(material, material_name, scene_file, resolver, NodeRegistry::builtin());
}

std::shared_ptr<const CompiledMaterial> compile_material(const nlohmann::json& material,
                                                         const std::string& material_name,
                                                         const std::string& scene_file,
                                                         ResourceResolver& resolver,
                                                         const NodeRegistry& registry) {
  const MaterialGraph graph = parse_material_graph(material, material_name, scene_file, resolver, registry);
  const GraphTyping typing = analyse_graph(graph);
  const FoldedGraph folded = fold_constants(graph, typing);
  BuiltProgram built = build_program(graph, typing, folded);
  return std::make_shared<const CompiledMaterial>(material_name, built.facts, std::move(built.program));
}

}  // namespace ochre
