#include "renderer/output/output_files.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <optional>

#include "renderer/image/display_image.h"
#include "renderer/image/image_library.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"
#include "spectra/input_error.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

// The path with "..", "." and the symbolic links of its existing part resolved.
fs::path resolved(const fs::path& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  if (error) return path.lexically_normal();
  const fs::path canonical = fs::weakly_canonical(absolute, error);
  return error ? absolute.lexically_normal() : canonical;
}

std::optional<FileIdentity> identity(const fs::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  return FileIdentity{static_cast<std::uint64_t>(info.st_dev), static_cast<std::uint64_t>(info.st_ino)};
}

struct Output {
  fs::path path;
  fs::path resolved;
  std::optional<FileIdentity> identity;
};

bool same_file(const Output& output, const fs::path& other_resolved, std::optional<FileIdentity> other) {
  return output.resolved == other_resolved || (output.identity && other && *output.identity == *other);
}

}  // namespace

void check_output_files(const std::vector<fs::path>& outputs, const InputFileLog& inputs) {
  std::vector<Output> checked;
  for (const fs::path& path : outputs) {
    try {
      check_output_writable(path);
    } catch (const ImageError& e) {
      throw InputError(e.what());
    }
    const Output output{path, resolved(path), identity(path)};
    for (const Output& earlier : checked)
      if (same_file(output, earlier.resolved, earlier.identity))
        throw InputError(
            fmt::format("cannot write {}: it is also given as output {}; two outputs cannot be one file",
                        path.string(), earlier.path.string()));
    for (const InputFileRecord& input : inputs.records())
      if (same_file(output, resolved(input.path), input.identity))
        throw InputError(fmt::format("cannot write {}: it is the {} {}, an input of this command",
                                     path.string(), input.kind, input.path.string()));
    checked.push_back(output);
  }
  // Display images are written through the image library module: load it now, so that a broken
  // installation stops the command before any work, not after the render.
  for (const fs::path& path : outputs)
    if (display_image_format(path)) (void)image_library();
}

}  // namespace ochre
