#pragma once
// NonFiniteTally: where the material program counts the NaN and infinite values it made finite
// (docs/nodes.md, "Non-finite values"). Every value a node writes (NodeArgs::set_*), every closure weight
// it passes on (add_weight) and every lobe weight and emission it adds goes through make_finite(): NaN
// becomes 0, +-inf the largest finite float of that sign, and the write is counted once. Downstream
// nodes, lobes and table lookups therefore only ever see finite values.
//
// The renderer gives each thread one tally (ShadingContext::nonfinite) and sums them into the render
// statistics; a null tally means "make finite, do not count".

#include <cstdint>

namespace ochre {

struct NonFiniteTally {
  uint64_t values = 0;  // writes that held a NaN or an infinity
  // Constant folding only: count but keep the value, so that the compiler reports it as an error on the
  // input it reaches (a constant must be finite) instead of folding a replacement.
  bool keep_values = false;
};

// Replaces the non-finite entries of values[0..n) (see above) and counts the write in `tally` (may be
// null). Called off the hot path, when a write was found not to be finite.
void make_finite(float* values, int n, NonFiniteTally* tally);

}  // namespace ochre
