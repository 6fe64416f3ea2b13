#pragma once
// CompiledMaterial: a material graph after compilation (material_compiler.h), ready to be
// evaluated at shading points by any number of threads at once.

#include <cstdint>
#include <string>

#include "materials/graph/material_facts.h"
#include "materials/graph/program.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/nodes/shading_context.h"

namespace ochre {

class CompiledMaterial {
 public:
  CompiledMaterial(std::string name, MaterialFacts facts, Program program);

  const std::string& name() const { return name_; }
  const MaterialFacts& facts() const { return facts_; }
  // Never 0 and never shared with another material of the process: the key of its closure in the per-thread
  // memo of uniform materials (uniform_closure_memo.h).
  uint64_t memo_key() const { return memo_key_; }

  // Evaluates the compiled program at a shading point; lobes go into `arena`; `out` is replaced by
  // the resulting lobes and emission. ctx.lambda must be set; ctx.textures when the material
  // has textures. Allocates nothing but the lobes.
  void evaluate(const ShadingContext& ctx, LobeArena& arena, Closure& out) const;

  // Instructions run per evaluation (node instructions, conversions and spectrum samplings).
  int instruction_count() const;
  // One line per instruction, in execution order (for tests and debugging).
  std::string listing() const;

 private:
  std::string name_;
  MaterialFacts facts_;
  Program program_;
  uint64_t memo_key_;
};

}  // namespace ochre
