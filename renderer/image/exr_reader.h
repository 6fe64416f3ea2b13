#pragma once
// Reads an OpenEXR file back into an ExrImage: every channel converted to float, all string attributes,
// the chromaticities when present. Used by tests and tools (image diff, merge).

#include <filesystem>

#include "renderer/image/exr_writer.h"

namespace ochre {

// Throws ImageError naming the file when it is missing, not an EXR, tiled with mipmaps, or has
// subsampled channels; InputError when it is not a regular file, is larger than the image limit
// (spectra/input_file.h) or its pixels would exceed the memory limit (renderer/util/memory_budget.h). The
// file is read through its own descriptor: OpenEXR never opens the path.
ExrImage read_exr(const std::filesystem::path& path);

}  // namespace ochre
