#include "materials/graph/uniform_closure_memo.h"

#include <array>
#include <cstdint>
#include <memory>

namespace ochre {

namespace {

struct Entry {
  uint64_t key = 0;  // 0: empty
  SampledSpectrum lambda;
  Closure closure;
  uint64_t nonfinite = 0;  // values the evaluation made finite
  std::unique_ptr<LobeArena> arena;
};

}  // namespace

void evaluate_memoized(const CompiledMaterial& material, const ShadingContext& ctx, LobeArena& arena,
                       Closure& out) {
  if (!material.facts().uniform_over_surface || !ctx.lambda) {
    material.evaluate(ctx, arena, out);
    return;
  }
  thread_local std::array<Entry, 64> table;
  Entry& e = table[material.memo_key() % table.size()];
  if (e.key != material.memo_key() || !(e.lambda == ctx.lambda->lambda())) {
    if (!e.arena) e.arena = std::make_unique<LobeArena>();
    e.key = 0;  // stays empty if the evaluation throws
    e.arena->reset();
    const uint64_t before = ctx.nonfinite ? ctx.nonfinite->values : 0;
    material.evaluate(ctx, *e.arena, e.closure);
    e.nonfinite = ctx.nonfinite ? ctx.nonfinite->values - before : 0;
    e.lambda = ctx.lambda->lambda();
    e.key = material.memo_key();
    out = e.closure;
    return;
  }
  if (ctx.nonfinite) ctx.nonfinite->values += e.nonfinite;
  out = e.closure;
}

}  // namespace ochre
