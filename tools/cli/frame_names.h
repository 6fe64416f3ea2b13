#pragma once
// Output names of a frame sequence (`ochre render --frames`, docs/cli.md#frame-sequences): the frame number,
// zero-padded to 4 digits (more when needed), goes before the extension: out.exr -> out.0007.exr,
// renders/out -> renders/out.0007.

#include <cstdint>
#include <string>

namespace ochre {

std::string frame_output_name(const std::string& path, uint64_t frame);

}  // namespace ochre
