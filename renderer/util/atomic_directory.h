#pragma once
// All-or-nothing output of a whole directory (ochre-regress --html, docs/tools.md): the files are written
// into a scratch directory beside the final one, and commit() puts it in place in one step, so that an
// error or a signal before then leaves an existing directory as it was and no partial directory behind.
//
//   AtomicDirectory report("out/report");
//   write_text_file(report.temp_path() / "index.html", html);
//   report.commit();  // replaces out/report only now
//
// The scratch directory holds files only (no subdirectories): the signal handler removes it with its
// files (renderer/util/signal_cleanup.h). A directory already at the final path is swapped with the new one
// atomically (renameat2 RENAME_EXCHANGE) where the filesystem allows, else renamed aside, replaced and
// put back on failure; the old one is removed after the swap.

#include <filesystem>

#include "renderer/util/signal_cleanup.h"

namespace ochre {

class AtomicDirectory {
 public:
  // Creates "<final>.tmp-<pid>-<counter>" beside final_path. Throws ImageError naming final_path when it
  // cannot.
  explicit AtomicDirectory(std::filesystem::path final_path);
  // Removes the scratch directory unless commit() succeeded.
  ~AtomicDirectory();
  AtomicDirectory(const AtomicDirectory&) = delete;
  AtomicDirectory& operator=(const AtomicDirectory&) = delete;

  const std::filesystem::path& temp_path() const { return temp_path_; }
  const std::filesystem::path& final_path() const { return final_path_; }

  // Puts the scratch directory at the final path (see above). Throws ImageError naming the final path
  // when it cannot; the existing directory is then unchanged.
  void commit();

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  TemporaryFileRegistration registration_;
  bool committed_ = false;
};

}  // namespace ochre
