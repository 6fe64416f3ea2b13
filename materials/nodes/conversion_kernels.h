#pragma once
// Run-time instructions the compiler inserts between nodes: implicit conversions of non-constant
// values, and sampling a pre-built constant spectrum at the path's wavelengths.

#include <cstdint>

#include "materials/nodes/node_args.h"
#include "materials/nodes/socket_type.h"
#include "spectra/spectrum.h"

namespace ochre {

// in[0] of type `from` -> out[0] of type `to` (float -> colour / vector / spectrum, colour ->
// spectrum by role); null when there is no such conversion.
NodeFn conversion_kernel(SocketType from, SocketType to, SpectralRole role);
// out[0] = the payload's spectrum (a MemoizedSpectrum, spectra/memoized_spectrum.h) sampled at ctx.lambda,
// memoized per thread for the path's wavelengths.
void sample_spectrum_kernel(const NodeArgs& a);

}  // namespace ochre
