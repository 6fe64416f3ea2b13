#pragma once
// Constants in a register frame (see node_args.h): how each type is laid out in floats.

#include <cstdint>
#include <vector>

#include "materials/nodes/node_value.h"

namespace ochre {

// Writes a constant at `at` (the frame must be large enough). Spectra must be flat
// (is_constant()); their value is repeated in every lane.
void store_constant(std::vector<float>& frame, uint16_t at, const NodeValue& v);
// Reads a value of `type` written at `at`; a spectrum becomes a ConstantSpectrum of lane 0.
NodeValue load_constant(const std::vector<float>& frame, uint16_t at, SocketType type);

}  // namespace ochre
