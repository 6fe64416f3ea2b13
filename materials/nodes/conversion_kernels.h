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
// The payload of sample_spectrum_kernel: a pre-built spectrum and its key in the per-thread memo of sampled
// values (spectra/wavelength_memo.h).
struct SampledSpectrumPayload {
  explicit SampledSpectrumPayload(const Spectrum* spectrum);
  const Spectrum* spectrum;
  uint64_t serial;
};
// out[0] = the payload's spectrum (a SampledSpectrumPayload) sampled at ctx.lambda, memoized per thread for
// the path's wavelengths.
void sample_spectrum_kernel(const NodeArgs& a);

}  // namespace ochre
