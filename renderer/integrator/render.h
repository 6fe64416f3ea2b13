#pragma once
// Renders a scene into a Film: oneTBB over 16x16 tiles, each pixel's samples in index order,
// so the image is bit-identical for any thread count.

#include <atomic>
#include <cstdint>
#include <functional>

#include "renderer/film/film.h"
#include "renderer/film/render_split.h"
#include "renderer/scene/polarization_mode.h"
#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene.h"

namespace ochre {

struct RenderStats {
  double seconds = 0.0;
  uint64_t samples = 0;           // camera samples (each of integrator.branches paths)
  uint64_t rays = 0;              // intersect queries
  uint64_t shadow_rays = 0;       // occlusion queries
  uint64_t discarded = 0;         // NaN / Inf samples, counted as zero
  uint64_t clamped = 0;           // samples beyond the film's range, clamped to it (kMaxSampleMagnitude)
  uint64_t nonfinite_values = 0;  // NaN / Inf values of material programs, made finite (non_finite_tally.h)
  int threads = 0;
  bool cancelled = false;  // stopped by the cancel flag: the film is incomplete
  double samples_per_second() const { return seconds > 0 ? samples / seconds : 0.0; }
  double rays_per_second() const { return seconds > 0 ? (rays + shadow_rays) / seconds : 0.0; }
  // Adds the figures of another render of the same scene (a later pass of samples).
  void add(const RenderStats& pass);
};

// Called with the number of pixel-samples finished since the last call (thread-safe use).
using ProgressCallback = std::function<void(uint64_t)>;

// The polarization mode a render of `scene` uses (the job's setting, the scene's facts, a Stokes output).
PolarizationChoice polarization_for(const Scene& scene, const RenderJob& job);

// Renders samples [settings.sample_begin, sample_begin + spp) of every pixel into `film` (with branches auto:
// paths, resolve_branches; its pilot's time counts in the stats). When `cancel`
// becomes true (set from any thread, e.g. on Ctrl-C in Python), every tile stops before its next pixel and
// render() returns with stats.cancelled: the film is then incomplete and must not be used.
RenderStats render(const Scene& scene, const RenderJob& job, Film& film,
                   const ProgressCallback& progress = {}, const std::atomic<bool>* cancel = nullptr);

// Renders samples `samples` of the pixels `rect` of the image into `film`, which is rect.width() x
// rect.height() (film pixel (0, 0) is image pixel (rect.x0, rect.y0)). Random numbers depend on the image
// pixel and the sample index only, so any split into rectangles and sample ranges, merged
// (Film::merge), gives the bits of one render. The job's branches must be resolved (resolve_branches): the
// range counts camera samples.
RenderStats render_range(const Scene& scene, const RenderJob& job, Film& film, const PixelRect& rect,
                         SampleRange samples, const ProgressCallback& progress = {},
                         const std::atomic<bool>* cancel = nullptr);

}  // namespace ochre
