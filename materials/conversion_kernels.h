#pragma once
// Run-time instructions the compiler inserts between nodes: implicit conversions of non-constant
// values, and sampling a pre-built constant spectrum at the path's wavelengths.

#include "materials/node_args.h"
#include "materials/socket_type.h"

namespace ochre {

// in[0] of type `from` -> out[0] of type `to` (float -> colour / vector / spectrum, colour ->
// spectrum by role); null when there is no such conversion.
NodeFn conversion_kernel(SocketType from, SocketType to, SpectralRole role);
// out[0] = payload (a const Spectrum*) sampled at ctx.lambda.
void sample_spectrum_kernel(const NodeArgs& a);

}  // namespace ochre
