#pragma once
// evaluate_memoized(): a material's closure, remembered per thread for the path's wavelengths when the
// material reads nothing of the shading point (MaterialFacts::uniform_over_surface).
//
// A path keeps its wavelengths from the camera to its last vertex, and a material uniform over the
// surface (every material of a Cornell box: a constant or tabulated Lambert) gives the same closure at every
// vertex that hits it. The first hit of each such material on a path runs its program; later hits copy the
// closure from a per-thread direct-mapped table (64 entries keyed by CompiledMaterial::memo_key(), a number
// never reused in the process; a collision only costs a recomputation). The lobes live in the entry's own
// arena, so the closure stays valid until the next evaluate_memoized() call on the same thread. The NaN / inf
// replacements of the first evaluation are counted again on every hit, so the render statistics do not change
// either.

#include "materials/graph/compiled_material.h"

namespace ochre {

// As material.evaluate(ctx, arena, out), but for a material uniform over the surface the lobes may live in
// the memo instead of `arena`: `out` is valid until the next call of this function on the same thread.
void evaluate_memoized(const CompiledMaterial& material, const ShadingContext& ctx, LobeArena& arena,
                       Closure& out);

}  // namespace ochre
