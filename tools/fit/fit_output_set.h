#pragma once
// ochre-fit's output files, written all or nothing: before any work, every output is checked (its
// directory writable, no two outputs the same file, no output one of the inputs); then each file is
// written completely under a temporary name (renderer/atomic_file.h) and only when all are written are
// they renamed over their final names, so an error or a failed plot leaves every existing file as it was.

#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "renderer/atomic_file.h"

namespace ochre {

// Throws InputError naming the output (and the input or output it collides with).
void check_fit_outputs(const std::vector<std::filesystem::path>& outputs,
                       const std::vector<std::filesystem::path>& inputs);

// Writes `text` to `path` (a temporary); throws ImageError naming `name` when it cannot.
void write_temporary_text(const std::filesystem::path& path, std::string_view text, const std::filesystem::path& name);

class FitOutputSet {
 public:
  // The temporary of final_path (write its temp_path()).
  AtomicOutput& add(const std::filesystem::path& final_path);
  // Writes `text` as the temporary of final_path.
  void add_text(const std::filesystem::path& final_path, std::string_view text);
  // Renames every temporary over its final name; throws ImageError naming the output that failed.
  void commit();

 private:
  std::vector<std::unique_ptr<AtomicOutput>> outputs_;
};

}  // namespace ochre
