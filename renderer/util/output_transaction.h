#pragma once
// All-or-nothing output of several files (`ochre render`'s EXR and PNGs, the files ochre-regress
// writes for a failing scene, ...): each file is written completely under its temporary name
// (AtomicOutput), and only then are they renamed over their final names, so that a failed or
// interrupted write leaves every existing output as it was.
//
//   OutputTransaction outputs;
//   write_exr(outputs.add("out.exr"), image);
//   write_display_png(outputs.add("out.png"), ...);
//   outputs.commit();  // nothing before this replaced anything
//
// A rename can still fail after the first ones succeeded (the directory was made read-only, or a file
// is owned by another user in a sticky directory): commit() then puts back the files already replaced,
// from hard links to them made before the first rename (where the filesystem has hard links), removes
// the outputs that did not exist before, and throws. SIGINT and SIGTERM are held back during the renames
// (renderer/util/signal_cleanup.h) and act when the set is complete.

#include <filesystem>
#include <memory>
#include <vector>

#include "renderer/util/atomic_file.h"

namespace ochre {

class OutputTransaction {
 public:
  OutputTransaction() = default;
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // The temporary for final_path; the writer writes output.temp_path() and does not commit.
  AtomicOutput& add(const std::filesystem::path& final_path);
  // An output written before it was known to belong to the set (e.g. only when a plot succeeded).
  AtomicOutput& add(std::unique_ptr<AtomicOutput> output);

  // Renames every temporary over its final path (see above). Throws ImageError naming the output that
  // failed; the temporaries are removed by the destructor.
  void commit();

 private:
  std::vector<std::unique_ptr<AtomicOutput>> outputs_;
};

}  // namespace ochre
