#include "renderer/integrator/guide_training.h"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "renderer/integrator/camera_sample.h"
#include "renderer/integrator/path_integrator.h"
#include "renderer/integrator/render.h"

namespace ochre {

namespace {

constexpr uint64_t kTrainingStream =
    0x6775696465ull;  // "guide": the training's numbers, apart from the render's
// The training traces this share of the render's paths, at least kMinTrainingPaths (fewer leave most cells
// unlearned), at most kMaxTrainingPaths (their records, ~100 bytes a path, are held until the guide is built;
// more learn little more) and at most kMaxSamplesPerPixel paths from each pixel of its grid.
constexpr double kTrainingShare = 0.1;
constexpr double kMinTrainingPaths = 65536;
constexpr double kMaxTrainingPaths = 524288;
constexpr uint32_t kMaxSamplesPerPixel = 64;

// The paths per pixel of the whole render: spp counts paths while branches are auto, camera samples of k
// paths once they are set (a resumed render's), so both give the same figure.
double render_paths(const RenderSettings& s) {
  const double per_pixel =
      s.branches == RenderSettings::kAutoBranches ? double(s.spp) : double(s.spp) * std::max(1, s.branches);
  return double(s.width) * double(s.height) * per_pixel;
}

// The training's own settings: one branch, the default roulette, each vertex's light chosen locally, no
// guide; nothing a pilot chooses, so that a resumed render (whose choices are set) trains the same paths.
RenderSettings training_settings(const RenderSettings& s) {
  RenderSettings t = s;
  t.branches = 1;
  t.rr_depth = RenderSettings::kDefaultRouletteDepth;
  t.light_selection = LightSelection::kLocal;
  t.guide = nullptr;
  return t;
}

}  // namespace

std::shared_ptr<const PathGuide> train_path_guide(const Scene& scene, const RenderJob& job,
                                                  GuideTraining* report) {
  GuideTraining local;
  GuideTraining& r = report ? *report : local;
  r = GuideTraining{};
  const RenderSettings& s = job.settings;
  if (s.max_depth < 2 || scene.lights.empty()) {
    r.summary = "nothing to guide (no light, or no bounce)";
    return nullptr;
  }
  const double target = std::clamp(kTrainingShare * render_paths(s), kMinTrainingPaths, kMaxTrainingPaths);
  // Every `stride`-th pixel in x and y (no more pixels than target paths), `samples` paths each.
  const double pixels = double(s.width) * double(s.height);
  const int stride = std::max(1, static_cast<int>(std::ceil(std::sqrt(pixels / target))));
  const int nx = (s.width + stride - 1) / stride, ny = (s.height + stride - 1) / stride;
  const auto samples = static_cast<uint32_t>(
      std::clamp(std::floor(target / (double(nx) * ny)), 1.0, double(kMaxSamplesPerPixel)));

  const PathIntegrator integrator(scene, training_settings(s), polarization_for(scene, job).mode);
  const RayCone cone = scene.camera.pixel_cone();
  const uint64_t seed = mix64(s.seed ^ kTrainingStream);
  const auto start = std::chrono::steady_clock::now();
  tbb::enumerable_thread_specific<std::vector<GuideRecord>> records;
  {
    const int threads = s.threads > 0 ? s.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
    tbb::parallel_for(0, ny, [&](int j) {
      thread_local LobeArena arena;
      std::vector<GuideRecord>& out = records.local();
      for (int i = 0; i < nx; ++i)
        for (uint32_t k = 0; k < samples; ++k) {
          const auto [sampler, lambda, ray] =
              camera_sample<IndependentSampler>(scene, seed, i * stride, j * stride, s.width, k);
          integrator.guide_training_path(ray, cone, lambda, sampler, arena, out);
        }
    });
  }
  // Which thread traced what does not matter: the guide sums integers. Moved, not copied.
  std::vector<std::vector<GuideRecord>> lists;
  for (std::vector<GuideRecord>& list : records) lists.push_back(std::move(list));
  auto guide = std::make_shared<const PathGuide>(PathGuide::build(lists));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.paths = uint64_t(nx) * uint64_t(ny) * samples;
  for (const auto& list : lists) r.records += list.size();
  r.usable_cells = guide->usable_cells();
  r.cells = guide->cell_count();
  r.trained = r.usable_cells > 0;
  r.summary = r.trained ? fmt::format("guided by {} of {} cells learned from {} paths ({:.2f} s)",
                                      r.usable_cells, r.cells, r.paths, r.seconds)
                        : fmt::format("not guided: {} training paths learned nothing", r.paths);
  return r.trained ? guide : nullptr;
}

}  // namespace ochre
