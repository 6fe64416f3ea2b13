#pragma once
// Helpers of the tests on input files, output files, limits and signals: minimal scenes, FIFOs, sparse
// files, and snapshots proving that a file was not touched.

#include <filesystem>
#include <string>
#include <vector>

namespace ochre::test {

// A valid scene (8x8, 1 spp, a plane under a constant environment) with the given members replacing the
// defaults: `materials`, `shapes` and `lights` are JSON members such as R"("shapes": [...])".
std::string minimal_scene(const std::string& materials = "", const std::string& shapes = "",
                          const std::string& lights = "", const std::string& extra = "");

// mkfifo(path); fails the test when it cannot.
void make_fifo(const std::filesystem::path& path);
// A file of `bytes` bytes that uses no disk (truncate).
void make_sparse_file(const std::filesystem::path& path, std::uintmax_t bytes);
// An 8-bit RGB PNG of w x h pixels.
void write_png(const std::filesystem::path& path, int width, int height);

// The bytes and modification time of a file, to prove it was left alone.
struct FileSnapshot {
  std::string bytes;
  std::filesystem::file_time_type mtime;
  bool operator==(const FileSnapshot&) const = default;
};
FileSnapshot snapshot(const std::filesystem::path& path);
// Writes `text` to `path` (creating directories) and sets its modification time an hour back, so that a
// rewrite shows.
void write_old_file(const std::filesystem::path& path, const std::string& text);

// Names of the entries of `dir` that look like temporaries ("*.tmp-*").
std::vector<std::string> temporaries_in(const std::filesystem::path& dir);

bool contains(const std::string& text, const std::string& part);

}  // namespace ochre::test
