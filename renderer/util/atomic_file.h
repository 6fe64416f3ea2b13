#pragma once
// Atomic file output: every image is written under a temporary name in the destination directory and
// renamed over the final name only when complete, so a crash or an error never leaves a truncated
// image and never damages the file being replaced (rename(2) is atomic within one filesystem). The
// temporary is registered for removal should SIGINT or SIGTERM end the process first
// (renderer/util/signal_cleanup.h). Several outputs that must all be written or none: OutputTransaction.

#include <filesystem>
#include <string_view>

#include "renderer/util/signal_cleanup.h"

namespace ochre {

class AtomicOutput {
 public:
  // Chooses a temporary name beside final_path: "<final name>.tmp-<pid>-<counter>".
  explicit AtomicOutput(std::filesystem::path final_path);
  // Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();

  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  // Where the writer must put the complete file.
  const std::filesystem::path& temp_path() const { return temp_path_; }
  const std::filesystem::path& final_path() const { return final_path_; }

  // Throws ImageError naming the final path unless the writer produced the temporary file, then flushes
  // it to disk. commit() does this first; OutputTransaction does it for every file before any rename.
  void check_written();
  // check_written(), then renames the temporary over the final path. Throws ImageError naming the final
  // path when the temporary file is missing or the rename fails (the temporary file is removed).
  void commit();
  bool committed() const { return committed_; }

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  TemporaryFileRegistration registration_;
  bool committed_ = false;
};

// "<final path>.tmp-<pid>-<counter>": a name beside final_path that no other output of this process uses.
std::filesystem::path temporary_name(const std::filesystem::path& final_path);

// Writes `text` to the output's temporary file without committing it (the caller commits, or an
// OutputTransaction commits a set); throws ImageError naming the final path when it cannot.
void write_text_file(const AtomicOutput& output, std::string_view text);
// Writes `text` to `path` through an AtomicOutput; throws ImageError naming the path when it cannot.
void write_text_file(const std::filesystem::path& path, std::string_view text);

// Throws ImageError("cannot write OUT: directory D does not exist" / "... is not writable" / "it is a
// directory" / "it is a symbolic link ..." / "it is a FIFO, not a regular file" / ...) when an output
// file could not be created, or when the path names something other than a regular file that renaming
// over it would replace behind the user's back (a link, a device such as /dev/null, a FIFO). The tools
// call it for every output before any work, so a bad output path fails early and leaves no partial
// output.
void check_output_writable(const std::filesystem::path& output);

}  // namespace ochre
