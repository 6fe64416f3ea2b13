#pragma once
// The part of the image a render command renders (docs/distributed.md): all samples of all pixels, or
// what --sample-range, --part and --region select; and the header of its partial-sum file.

#include <string>

#include "renderer/integrator/render.h"
#include "renderer/output/partial_sums.h"
#include "tools/ochre/render_command.h"

namespace ochre {

struct RenderPart {
  PixelRect rect;
  SampleRange samples;
};

// InputError naming the option when the selection does not fit the scene or -o is missing.
RenderPart select_part(const RenderCommand& command, const RenderSettings& settings);

// The header of the partial-sum file of `part` holding samples [part.samples.begin, samples_done): the
// render's identity, where the pixels sit, the samples held, the NaN/Inf counts, and notes for
// `ochre merge` (the scene, the display settings).
PartialSumsHeader partial_header(const Scene& scene, const RenderJob& job, const std::string& content_hash,
                                 const RenderPart& part, uint32_t samples_done, const RenderStats& stats);

}  // namespace ochre
