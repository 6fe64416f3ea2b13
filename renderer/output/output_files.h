#pragma once
// The checks every tool makes on the files it is asked to write, before any work (docs/cli.md, "Output
// files"), so that no output destroys data:
// - each output can be created and is not a directory, a symbolic link, a device (/dev/null included),
//   a FIFO or a socket (check_output_writable, renderer/util/atomic_file.h);
// - no two outputs are the same file;
// - no output is one of the command's inputs: the scene, a mesh, a texture, a spectrum CSV, the OCIO
//   config, any file the command has read while recording an InputFileLog (spectra/input_file.h).
// Files are compared by path (absolute, with "..", "." and symbolic links of the directories resolved)
// and, for files that exist, by identity (device and inode), so hard links and other spellings of one
// file are caught.

#include <filesystem>
#include <vector>

#include "spectra/input_file.h"

namespace ochre {

// Throws InputError naming the output (and the input or the other output it collides with); loads the
// image library (renderer/image/image_library.h) when an output is a PNG or JPEG image, and throws its
// ImageError when the module cannot be loaded.
void check_output_files(const std::vector<std::filesystem::path>& outputs, const InputFileLog& inputs);

}  // namespace ochre
