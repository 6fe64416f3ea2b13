#pragma once
// A long render in passes of sample indices (docs/distributed.md, "Checkpoints"): after each pass every
// pixel of the rectangle holds the samples [begin, next), a clean state that a checkpoint records exactly
// and that a resumed render continues bit for bit (the film's fixed-point sums do not depend on how the
// samples are grouped). Pass sizes adapt to the measured speed so that a pass takes about
// `pass_seconds`: a stop request (a signal) waits at most that long, checkpoints come on time, and no
// pass runs past a time limit.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>

#include "renderer/integrator/render.h"

namespace ochre {

struct PassSchedule {
  using Clock = std::chrono::steady_clock;
  double pass_seconds = 1.0;                  // aimed duration of a pass
  double checkpoint_interval = 0.0;           // seconds between checkpoints; 0: none on the way
  std::optional<Clock::time_point> deadline;  // no pass may end after it (--time-limit)
};

enum class PassStop { finished, stop_requested, deadline };

struct PassResult {
  uint32_t next = 0;  // samples [samples.begin, next) of every pixel are in the film
  PassStop stop = PassStop::finished;
  RenderStats stats;  // of the passes rendered
};

// Renders samples `samples` of the pixels `rect` into `film` in passes. `checkpoint(next, stats)` is called
// at a pass boundary whenever checkpoint_interval has passed since the start or the last checkpoint
// (not after the last pass); `stop_requested()` is asked before each pass.
PassResult render_in_passes(const Scene& scene, const RenderJob& job, Film& film, const PixelRect& rect,
                            SampleRange samples, const PassSchedule& schedule,
                            const ProgressCallback& progress,
                            const std::function<void(uint32_t next, const RenderStats& so_far)>& checkpoint,
                            const std::function<bool()>& stop_requested);

}  // namespace ochre
