#pragma once
// Checkpoints of `ochre render` (docs/distributed.md, "Checkpoints"): partial-sum files of the samples
// done so far, with notes recording what `ochre render --resume CHECKPOINT` needs to continue the
// render: the scene, its settings (the identity), the samples aimed at, the outputs.

#include <filesystem>
#include <optional>

#include "renderer/output/partial_sums.h"
#include "tools/ochre/render_command.h"
#include "tools/ochre/render_part.h"

namespace ochre {

struct OutputSettings;

// Records the resume notes in a checkpoint's header: the samples aimed at (`part`), whether the outputs
// are partial sums (`split`), the output paths (absolute), the checkpoint interval (seconds; none when
// `interval` is empty), which a resumed render keeps unless its command line gives another, and the seconds
// spent rendering the samples held, over every run that rendered them (none when unknown: a resumed
// checkpoint that did not record them), from which ochre info and ochre-slurm --status estimate the time
// left (docs/distributed.md).
void add_checkpoint_notes(PartialSumsHeader& header, const RenderPart& part, bool split,
                          const OutputSettings& out, std::optional<double> interval,
                          std::optional<double> seconds);

// The rendering seconds a checkpoint records (ochre.checkpoint.seconds); none when it records none or the
// note is not a finite number >= 0.
std::optional<double> recorded_seconds(const PartialSumsHeader& header);

// The command a checkpoint continues: its scene (unless `given` names the scene at another path),
// settings, layers and outputs, with what the resuming command line may set (outputs, display, threads,
// checkpoint options, quiet, memory limit). InputError naming the checkpoint and the note when it is not a
// checkpoint.
RenderCommand resumed_command(const RenderCommand& given, const PartialSumsFile& checkpoint);

// Refuses (InputError naming the checkpoint and the field) a checkpoint whose identity differs from the
// render's: another version of ochre, a changed scene or referenced file.
void check_resumable(const PartialSumsFile& checkpoint, const RenderIdentity& render);

// The first sample not yet rendered: the end of the checkpoint's single coverage piece, which must be
// `part`'s rectangle from its first sample (InputError naming the checkpoint otherwise).
uint32_t resume_point(const PartialSumsFile& checkpoint, const RenderPart& part);

// Where checkpoints go without --checkpoint: beside the first output, "NAME.checkpoint.exr".
std::filesystem::path default_checkpoint_path(const OutputSettings& out);

}  // namespace ochre
