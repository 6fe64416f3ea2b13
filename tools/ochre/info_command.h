#pragma once
// `ochre info PARTS...` (docs/cli.md, "ochre info"): one line per partial-sum file or checkpoint saying what
// it holds: the frame, the pixels, the samples (and, of a checkpoint, the samples aimed at, the share done,
// the rendering time and the time left at that pace). Reads the headers only. Used by ochre-slurm --status
// (docs/distributed.md). Returns 0, or 2 when a file could not be read (the others are still listed).

#include <string>
#include <vector>

namespace ochre {

struct InfoCommand {
  std::vector<std::string> parts;
};

int run_info(const InfoCommand& command);

}  // namespace ochre
