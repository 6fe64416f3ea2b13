#pragma once
// Last compiler passes: dead-node removal (what the output does not reach is dropped), register
// allocation, instruction emission, and the material's facts.

#include "materials/graph/graph_folding.h"
#include "materials/graph/material_facts.h"
#include "materials/graph/program.h"

namespace ochre {

struct BuiltProgram {
  Program program;
  MaterialFacts facts;
};

BuiltProgram build_program(const MaterialGraph& graph, const GraphTyping& typing, const FoldedGraph& folded);

}  // namespace ochre
