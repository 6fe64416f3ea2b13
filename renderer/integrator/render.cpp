#include "renderer/integrator/render.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>

#include "renderer/film/noise_threshold.h"
#include "renderer/geometry/surface_shading.h"
#include "renderer/integrator/branch_choice.h"
#include "renderer/integrator/camera_sample.h"
#include "renderer/integrator/path_integrator.h"
#include "spectra/cie.h"

namespace ochre {

namespace {

constexpr int kTileSize = 16;

struct TileCounters {
  std::atomic<uint64_t> samples{0}, rays{0}, shadow_rays{0}, discarded{0}, clamped{0}, nonfinite_values{0};
};

// First-hit AOVs of one sample: albedo as the colour it has under D65 (white = 1), the normal, the depth.
void add_aovs(Film& film, int x, int y, const FirstHit& first, const SampledWavelengths& lambda) {
  static const SpectrumPtr white = d65();
  XYZ albedo{0, 0, 0};
  if (first.hit) albedo = sampled_to_xyz(first.albedo * white->sample(lambda), lambda);
  if (!std::isfinite(albedo.x) || !std::isfinite(albedo.y) || !std::isfinite(albedo.z)) albedo = {0, 0, 0};
  film.add_aov_sample(x, y, albedo, {first.normal.x, first.normal.y, first.normal.z},
                      first.hit ? first.depth : 0.0f);
}

// What became of a camera sample: added, discarded (NaN / Inf: counted, adds zero) or clamped to the film's
// range (added at kMaxSampleMagnitude).
enum class SampleFate { kAdded, kDiscarded, kClamped };

bool beyond_film_range(const XYZ& v) {
  return std::fabs(v.x) > kMaxSampleMagnitude || std::fabs(v.y) > kMaxSampleMagnitude ||
         std::fabs(v.z) > kMaxSampleMagnitude;
}

// The groups' S0 of one sample (docs/lights.md, "Light groups"): per group, or per group and bin of each
// wavelength's share (the shares sum to the group's value: sensor_value is linear in the lanes).
void add_group_samples(Film& film, int x, int y, const SampledSpectrum* groups,
                       const SampledWavelengths& lambda, const SensorResponse* sensor) {
  const size_t count = film.light_groups().size();
  if (film.group_bins() == 1) {
    for (size_t g = 0; g < count; ++g)
      film.add_group_sample(x, y, g, 0, sensor_value(sensor, groups[g], lambda));
    return;
  }
  for (size_t g = 0; g < count; ++g)
    for (int i = 0; i < kSpectrumSamples; ++i) {
      SampledSpectrum lane(0.0f);
      lane[i] = groups[g][i];
      film.add_group_sample(x, y, g, film.group_bin(lambda[i]), sensor_value(sensor, lane, lambda));
    }
}

SampleFate add_sample(Film& film, int x, int y, const SensorStokes& S, const SampledWavelengths& lambda,
                      const SensorResponse* sensor, const SampledSpectrum* groups) {
  XYZ xyz = sensor_value(sensor, S[0], lambda);
  std::array<XYZ, 3> s123{};
  bool finite = is_finite(xyz);
  if (film.has_stokes())
    for (int c = 0; c < 3; ++c) {
      s123[c] = sensor_value(sensor, S[c + 1], lambda);
      finite = finite && is_finite(s123[c]);
    }
  if (!finite) {
    film.add_sample(x, y, {0, 0, 0});
    if (film.has_stokes()) film.add_stokes_sample(x, y, {});
    return SampleFate::kDiscarded;
  }
  bool clamped = beyond_film_range(xyz);
  for (const XYZ& s : s123) clamped = clamped || beyond_film_range(s);
  film.add_sample(x, y, xyz);
  if (groups) add_group_samples(film, x, y, groups, lambda, sensor);
  if (film.has_stokes()) film.add_stokes_sample(x, y, s123);
  if (film.spectral_bins() > 0)
    for (int c = 0; c < (film.has_stokes() ? 4 : 1); ++c) film.add_spectral_sample(x, y, S[c], lambda, c);
  return clamped ? SampleFate::kClamped : SampleFate::kAdded;
}

// One tile of the rendered rectangle: image pixels [x0, x1) x [y0, y1).
struct Tile {
  int x0, y0, x1, y1;
};

template <class Sampler>
void render_tile(const Scene& scene, const RenderSettings& s, const PathIntegrator& integrator,
                 const Tile& tile, const PixelRect& rect, SampleRange samples, Film& film,
                 TileCounters& counters, const ProgressCallback& progress, const std::atomic<bool>* cancel) {
  thread_local LobeArena arena;
  // Progress counts every sample of the range, also those a pixel of a noise-threshold render skips.
  // The tile runs on this thread from start to end (no TBB call inside): its values are the increase.
  const NonFiniteTally& nonfinite = thread_non_finite_tally();
  const uint64_t nonfinite_before = nonfinite.values;
  PathStats stats;
  const RayCone cone = scene.camera.pixel_cone();
  const SensorResponse* sensor = scene.sensor.get();
  uint64_t taken = 0, discarded = 0, clamped = 0;
  const double threshold = s.noise_threshold;
  // Light groups: the S0 of each group's lights, per sample (docs/lights.md, "Light groups").
  const size_t group_count = film.light_groups().size();
  std::array<SampledSpectrum, kMaxLightGroups> groups;
  SampledSpectrum* const group_sums = group_count > 0 ? groups.data() : nullptr;
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x) {
      if (cancel && cancel->load(std::memory_order_relaxed)) return;  // at a pixel boundary
      // Random numbers and rays follow the pixel's place in the image; the film holds only the rectangle.
      const int fx = x - rect.x0, fy = y - rect.y0;
      for (uint32_t k = samples.begin; k < samples.end; ++k) {
        if (threshold > 0.0 && !pixel_takes_sample(film, fx, fy, k, threshold)) break;
        ++taken;
        const auto [sampler, lambda, ray] = camera_sample<Sampler>(scene, s.seed, x, y, s.width, k);
        FirstHit first;
        for (size_t g = 0; g < group_count; ++g) groups[g] = SampledSpectrum(0.0f);
        const SensorStokes S = integrator.radiance(ray, cone, lambda, sampler, arena, stats,
                                                   film.has_aovs() ? &first : nullptr, group_sums);
        if (film.has_aovs()) add_aovs(film, fx, fy, first, lambda);
        const SampleFate fate = add_sample(film, fx, fy, S, lambda, sensor, group_sums);
        if (fate == SampleFate::kDiscarded) ++discarded;
        if (fate == SampleFate::kClamped) ++clamped;
      }
    }
  }
  counters.samples += taken;
  counters.rays += stats.rays;
  counters.shadow_rays += stats.shadow_rays;
  counters.discarded += discarded;
  counters.clamped += clamped;
  counters.nonfinite_values += nonfinite.values - nonfinite_before;
  if (progress) progress(static_cast<uint64_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0) * samples.size());
}

}  // namespace

void RenderStats::add(const RenderStats& pass) {
  seconds += pass.seconds;
  samples += pass.samples;
  rays += pass.rays;
  shadow_rays += pass.shadow_rays;
  discarded += pass.discarded;
  clamped += pass.clamped;
  nonfinite_values += pass.nonfinite_values;
  threads = pass.threads;
}

PolarizationChoice polarization_for(const Scene& scene, const RenderJob& job) {
  const PolarizationNeeds needs{scene.polarizing_filters, scene.polarizing_materials,
                                scene.polarization_significance};
  return choose_polarization_mode(job.settings.polarization, needs, job.outputs.stokes);
}

RenderStats render(const Scene& scene, const RenderJob& job, Film& film, const ProgressCallback& progress,
                   const std::atomic<bool>* cancel) {
  if (has_automatic_choices(job.settings)) {
    // The pilot's and the guide's training time count as the render's.
    BranchChoice choice;
    const RenderJob resolved = resolve_branches(scene, job, &choice);
    RenderStats stats = render(scene, resolved, film, progress, cancel);
    stats.seconds += choice.seconds + choice.guide.seconds;
    return stats;
  }
  const RenderSettings& s = job.settings;
  return render_range(scene, job, film, {0, 0, s.width, s.height}, {s.sample_begin, s.sample_begin + s.spp},
                      progress, cancel);
}

RenderStats render_range(const Scene& scene, const RenderJob& job, Film& film, const PixelRect& rect,
                         SampleRange samples, const ProgressCallback& progress,
                         const std::atomic<bool>* cancel) {
  const RenderSettings& s = job.settings;
  if (rect.empty() || !PixelRect{0, 0, s.width, s.height}.contains(rect) || film.width() != rect.width() ||
      film.height() != rect.height())
    throw std::invalid_argument("render_range: the rectangle does not fit the image or the film");
  if (s.branches == RenderSettings::kAutoBranches || s.rr_depth == RenderSettings::kAutoRoulette)
    throw std::invalid_argument(
        "render_range: branches or rr_depth auto: resolve_branches first (sample ranges count camera "
        "samples)");
  if (!film.light_groups().empty() && film.light_groups() != scene.light_groups)
    throw std::invalid_argument("render_range: the film's light groups are not the scene's");
  // A pixel of a noise-threshold render decides from all its samples so far: the film holds [0, begin).
  if (s.noise_threshold > 0.0 && s.sample_begin != 0)
    throw std::invalid_argument("render_range: a noise-threshold render starts at sample 0");
  const int threads = s.threads > 0 ? s.threads : tbb::this_task_arena::max_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
  const PathIntegrator integrator(scene, s, polarization_for(scene, job).mode);
  TileCounters counters;
  const int tiles_x = (rect.width() + kTileSize - 1) / kTileSize;
  const int tiles_y = (rect.height() + kTileSize - 1) / kTileSize;
  const auto tile_at = [&](int t) {
    const int x0 = rect.x0 + (t % tiles_x) * kTileSize, y0 = rect.y0 + (t / tiles_x) * kTileSize;
    return Tile{x0, y0, std::min(rect.x1, x0 + kTileSize), std::min(rect.y1, y0 + kTileSize)};
  };

  const auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(
      tbb::blocked_range<int>(0, tiles_x * tiles_y),
      [&](const tbb::blocked_range<int>& range) {
        for (int t = range.begin(); t != range.end(); ++t)
          if (s.sampler == SamplerKind::kSobol)
            render_tile<SobolSampler>(scene, s, integrator, tile_at(t), rect, samples, film, counters,
                                      progress, cancel);
          else
            render_tile<IndependentSampler>(scene, s, integrator, tile_at(t), rect, samples, film, counters,
                                            progress, cancel);
      },
      tbb::simple_partitioner());
  RenderStats stats;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.samples = counters.samples;
  stats.rays = counters.rays;
  stats.shadow_rays = counters.shadow_rays;
  stats.discarded = counters.discarded;
  stats.clamped = counters.clamped;
  stats.nonfinite_values = counters.nonfinite_values;
  stats.threads = threads;
  stats.cancelled = cancel && cancel->load();
  return stats;
}

}  // namespace ochre
