#pragma once
// Atomic file output: every image is written under a temporary name in the destination directory and
// renamed over the final name only when complete, so a crash or an error never leaves a truncated
// image and never damages the file being replaced (rename(2) is atomic within one filesystem).

#include <filesystem>
#include <string_view>

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

  // Flushes the temporary file to disk and renames it over the final path. Throws ImageError naming the
  // final path when the temporary file is missing or the rename fails (the temporary file is removed).
  void commit();

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  bool committed_ = false;
};

// Writes `text` to `path` through an AtomicOutput; throws ImageError naming the path when it cannot.
void write_text_file(const std::filesystem::path& path, std::string_view text);

// Throws ImageError("cannot write OUT: directory D does not exist" / "... is not writable" / ...) when
// an output file could not be created. The renderer calls it for every output before rendering, so a
// bad output path fails early and leaves no partial output.
void check_output_writable(const std::filesystem::path& output);

}  // namespace ochre
