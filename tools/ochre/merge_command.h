#pragma once
// `ochre merge PARTS... -o OUT.exr [--png OUT.png] [--sums OUT.exr] [--partial]` (docs/distributed.md):
// checks that the partial-sum files come from one render and cover every sample of every pixel exactly
// once, adds their exact sums and writes the image a single render would have written, bit for bit.
// Returns the exit code (docs/cli.md, "Exit codes"; tools/cli/program.h): 0 success, 4 for --check when
// samples are missing, 2 when memory runs out (nothing written); bad input throws (run_program: exit 2).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ochre {

struct MergeCommand {
  std::vector<std::string> parts;
  std::string exr, png;  // the final image (as `ochre render -o/--png`)
  std::string sums;      // the merged partial sums, to merge again with further parts
  bool partial = false;  // a subset of the samples is fine (a lower-sample image); overlaps never are
  bool check = false;    // only check the parts and report what is missing (exit 4); write nothing
  bool quiet = false;
  std::optional<std::string> ocio_config, display, view;
  std::optional<float> exposure;
  std::optional<std::uint64_t> memory_limit;
};

int run_merge(const MergeCommand& command);

}  // namespace ochre
