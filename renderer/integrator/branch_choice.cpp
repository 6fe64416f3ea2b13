#include "renderer/integrator/branch_choice.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "renderer/film/noise_threshold.h"
#include "renderer/integrator/camera_sample.h"
#include "renderer/integrator/path_integrator.h"
#include "renderer/integrator/render.h"

namespace ochre {

namespace {

// The pilot: a grid of at most kGridWidth pixels across (rows in the image's aspect), kPilotSamples camera
// samples each, two continuations per sample; from its own seed.
constexpr int kGridWidth = 48;
constexpr uint32_t kPilotSamples = 8;
constexpr uint64_t kPilotSeed = 0x70696c6f74ull;  // "pilot"
// The pilot runs only where the render traces at least this many times the pilot's paths (of every roulette
// start it weighs): it then costs at most a tenth of the render.
constexpr double kMinRenderToPilot = 10.0;
constexpr int kMaxAutoBranches = 16;
constexpr double kUncertainties = 1.0;  // how far above its estimate V0 is taken
// The earlier roulette start the pilot weighs against the default; by how much it, or sampling every light,
// must win.
constexpr int kEarlyRoulette = 3;
constexpr double kChoiceMargin = 0.97;
constexpr uint32_t kMinCameraSamples = 4;  // a pixel keeps this many places and wavelength sets at least
// A shadow ray costs about a quarter of a ray whose hit is shaded; a camera sample's own work (wavelengths,
// camera ray set-up, the film) about half of one (measured on the cave and the Cornell box: the first vertex
// is a third of a sample's time there, docs/engineering/performance-record.md).
constexpr double kShadowRayCost = 0.25;
constexpr double kCameraSampleCost = 0.5;
// The relMSE's epsilon (docs/performance.md): pixels near black weigh like pixels of 0.1.
constexpr double kRelativeEpsilon = 1e-2;

struct GridPixel {
  int x, y;
};

std::vector<GridPixel> pilot_grid(int width, int height) {
  const int nx = std::min(width, kGridWidth);
  const int ny = std::clamp(static_cast<int>(std::lround(double(nx) * height / width)), 1, height);
  std::vector<GridPixel> grid;
  grid.reserve(static_cast<size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      grid.push_back({static_cast<int>((i + 0.5) * width / nx), static_cast<int>((j + 0.5) * height / ny)});
  return grid;
}

// What one pixel's pilot samples say: the relative variances of the shared part (V0) and of a continuation
// given the shared part (V1), summed over X, Y, Z; and the rays.
struct PixelPilot {
  double shared_variance = 0, branch_variance = 0;
  double shared_cost = 0, branch_cost = 0;
};

// Independent numbers whatever the render's sampler: a stratified sampler's samples and branches are
// anti-correlated (the two branches of a Sobol sample fall in opposite halves of every dimension), which
// would bias the variance estimates.
PixelPilot pilot_pixel(const Scene& scene, const RenderSettings& s, const PathIntegrator& integrator,
                       const GridPixel& pixel) {
  thread_local LobeArena arena;
  const RayCone cone = scene.camera.pixel_cone();
  const SensorResponse* sensor = scene.sensor.get();
  std::array<std::array<double, kPilotSamples>, 3> estimate{}, spread{};  // per channel and sample
  PixelPilot out;
  for (uint32_t i = 0; i < kPilotSamples; ++i) {
    const auto [sampler, lambda, ray] =
        camera_sample<IndependentSampler>(scene, kPilotSeed, pixel.x, pixel.y, s.width, i);
    const BranchPilotSample p = integrator.pilot_sample(ray, cone, lambda, sampler, arena);
    const XYZ shared = sensor_value(sensor, p.shared, lambda);
    const XYZ a = sensor_value(sensor, p.branch[0], lambda), b = sensor_value(sensor, p.branch[1], lambda);
    const double sv[3] = {shared.x, shared.y, shared.z}, av[3] = {a.x, a.y, a.z}, bv[3] = {b.x, b.y, b.z};
    for (int c = 0; c < 3; ++c) {
      // The sample with its two continuations averaged, and half the squared difference of the two: an
      // unbiased estimate of a continuation's variance given the shared part.
      estimate[c][i] = sv[c] + 0.5 * (av[c] + bv[c]);
      spread[c][i] = 0.5 * (av[c] - bv[c]) * (av[c] - bv[c]);
    }
    out.shared_cost +=
        double(p.shared_rays) + kShadowRayCost * double(p.shared_shadow_rays) + kCameraSampleCost;
    out.branch_cost += 0.5 * (double(p.branch_rays) + kShadowRayCost * double(p.branch_shadow_rays));
  }
  for (int c = 0; c < 3; ++c) {
    double mean = 0, v1 = 0;
    for (uint32_t i = 0; i < kPilotSamples; ++i) {
      mean += estimate[c][i] / kPilotSamples;
      v1 += spread[c][i] / kPilotSamples;
    }
    double var = 0;
    for (uint32_t i = 0; i < kPilotSamples; ++i) var += (estimate[c][i] - mean) * (estimate[c][i] - mean);
    var /= kPilotSamples - 1;
    // var estimates V0 + V1 / 2 (two continuations averaged).
    const double weight = 1.0 / (mean * mean + kRelativeEpsilon);
    if (!std::isfinite(var) || !std::isfinite(v1) || !std::isfinite(weight)) continue;
    out.shared_variance += weight * (var - 0.5 * v1);
    out.branch_variance += weight * v1;
  }
  return out;
}

// The largest power of two that divides n (n > 0).
uint32_t power_of_two_dividing(uint32_t n) {
  return n & (~n + 1u);
}

// The pilot's sums for one roulette start: V0 (with its uncertainty), V1 and the costs, per camera sample.
struct PilotSums {
  double shared_variance = 0, shared_uncertainty = 0, branch_variance = 0;
  double shared_cost = 0, branch_cost = 0;
};

PilotSums run_pilot(const Scene& scene, const RenderJob& job, const std::vector<GridPixel>& grid,
                    int rr_depth, LightSelection selection) {
  const RenderSettings& s = job.settings;
  RenderSettings pilot_settings = s;
  pilot_settings.branches = 2;
  pilot_settings.rr_depth = rr_depth;
  pilot_settings.light_selection = selection;
  const PathIntegrator integrator(scene, pilot_settings, polarization_for(scene, job).mode);
  std::vector<PixelPilot> pixels(grid.size());
  {
    const int threads = s.threads > 0 ? s.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
    tbb::parallel_for(size_t(0), grid.size(),
                      [&](size_t i) { pixels[i] = pilot_pixel(scene, s, integrator, grid[i]); });
  }
  // Summed in pixel order: the same figures for any thread count.
  PilotSums sum;
  for (const PixelPilot& p : pixels) {
    sum.shared_variance += p.shared_variance;
    sum.branch_variance += p.branch_variance;
    sum.shared_cost += p.shared_cost;
    sum.branch_cost += p.branch_cost;
  }
  // The pixels' spread: an upper bound of the noise of the sum of their V0 estimates.
  const double mean_shared = sum.shared_variance / double(pixels.size());
  double spread = 0;
  for (const PixelPilot& p : pixels)
    spread += (p.shared_variance - mean_shared) * (p.shared_variance - mean_shared);
  sum.shared_uncertainty = std::sqrt(spread);
  const double samples = double(kPilotSamples) * double(grid.size());
  sum.shared_cost /= samples;
  sum.branch_cost /= samples;
  return sum;
}

// One pilot's settings: how lights are sampled and where roulette starts.
struct Candidate {
  LightSelection selection;
  int rr_depth;
};

// ", every light sampled at each vertex" where that was chosen (the summary line), else nothing.
std::string lights_phrase(const Scene& scene, const BranchChoice& choice) {
  if (choice.light_selection != LightSelection::kAll || scene.lights.size() < 2) return "";
  return fmt::format(", all {} lights sampled at each vertex", scene.lights.size());
}

// The time to a given error with k continuations: (V0 + V1 / k)(c0 + k c1), in the pilot's units.
double time_to_error(int k, double v0, const PilotSums& p) {
  return (v0 + std::max(p.branch_variance, 0.0) / k) * (p.shared_cost + k * p.branch_cost);
}

}  // namespace

BranchChoice choose_branches(const Scene& scene, const RenderJob& job) {
  const RenderSettings& s = job.settings;
  const bool auto_branches = s.branches == RenderSettings::kAutoBranches;
  const bool auto_roulette = s.rr_depth == RenderSettings::kAutoRoulette;
  const bool auto_lights = s.light_selection == LightSelection::kAuto;
  BranchChoice choice;
  choice.branches = auto_branches ? 1 : s.branches;
  choice.rr_depth = auto_roulette ? RenderSettings::kDefaultRouletteDepth : s.rr_depth;
  choice.light_selection = auto_lights ? LightSelection::kLocal : s.light_selection;
  const auto plain = [&](const std::string& why) {
    choice.reason =
        fmt::format("{} branch{}, roulette from depth {}{} ({})", choice.branches,
                    choice.branches == 1 ? "" : "es", choice.rr_depth, lights_phrase(scene, choice), why);
    return choice;
  };
  if (!auto_branches && !auto_roulette && !auto_lights) return plain("as set");
  // Branch counts: powers of two dividing spp (and sample_begin) that leave kMinCameraSamples camera samples.
  // A pixel of a noise-threshold render decides at 16, 32, ... camera samples
  // (renderer/film/noise_threshold.h): its counts leave it at least one decision before the maximum.
  std::vector<int> counts{choice.branches};
  const bool threshold = s.noise_threshold > 0.0;
  const uint32_t min_camera_samples = threshold ? 2 * kFirstNoiseDecision : kMinCameraSamples;
  if (auto_branches) {
    uint32_t cap = std::min<uint32_t>(kMaxAutoBranches, s.spp / min_camera_samples);
    cap = std::min(cap, power_of_two_dividing(s.spp));
    if (s.sample_begin > 0) cap = std::min(cap, power_of_two_dividing(s.sample_begin));
    for (uint32_t k = 2; k <= cap; k *= 2) counts.push_back(static_cast<int>(k));
  }
  // The pilots, by priority: the defaults (one light per vertex, roulette from the default start) first; with
  // 2-8 lights every light sampled from the default start; roulette from kEarlyRoulette (lever a, m of the
  // performance record: earlier costs more than it saves, later rarely matters) where the paths reach it;
  // both. A render too small for all of them to cost at most a tenth of it drops them from the end, but keeps
  // two (or all there are, if fewer).
  const bool early = auto_roulette && kEarlyRoulette < s.max_depth;
  const bool every_light = auto_lights && scene.local_light_selection(LightSelection::kLocal);
  std::vector<Candidate> candidates{{choice.light_selection, choice.rr_depth}};
  if (every_light) candidates.push_back({LightSelection::kAll, choice.rr_depth});
  if (early) candidates.push_back({choice.light_selection, kEarlyRoulette});
  if (every_light && early) candidates.push_back({LightSelection::kAll, kEarlyRoulette});
  if (counts.size() == 1 && candidates.size() == 1)
    return plain(fmt::format("{} paths per pixel: fewer than {} camera samples of 2{}", s.spp,
                             min_camera_samples,
                             threshold ? " (a noise threshold's first decision and one more)" : ""));
  const std::vector<GridPixel> grid = pilot_grid(s.width, s.height);
  const double render_paths = double(s.width) * s.height * s.spp;
  const double pilot_paths = 2.0 * kPilotSamples * double(grid.size());
  const auto affordable = static_cast<size_t>(render_paths / (kMinRenderToPilot * pilot_paths));
  if (affordable < std::min<size_t>(candidates.size(), 2))
    return plain(fmt::format("a render of {:.3g} paths is too small for the pilot", render_paths));
  candidates.resize(std::min(candidates.size(), affordable));

  const auto start = std::chrono::steady_clock::now();
  std::vector<PilotSums> pilots;
  for (const Candidate& c : candidates)
    pilots.push_back(run_pilot(scene, job, grid, c.rr_depth, c.selection));
  choice.piloted = true;
  choice.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // V0 does not depend on the roulette (it starts past the shared part), but on the light sampling (the
  // first vertex's light sample is shared): each selection's pilot from the default start serves its other
  // start. Where the shared part is nearly noise-free it is a small difference of noisy sums, taken at the
  // upper end of its uncertainty, which errs towards fewer branches, the cheaper mistake.
  const auto shared_variance = [](const PilotSums& p) {
    const double v1 = std::max(p.branch_variance, 0.0);
    return std::max(std::max(p.shared_variance, 0.0) + kUncertainties * p.shared_uncertainty, 1e-6 * v1);
  };
  const int default_start = choice.rr_depth;  // choice.rr_depth changes below, as candidates win
  const auto v0_of = [&](LightSelection selection) {
    for (size_t i = 0; i < candidates.size(); ++i)
      if (candidates[i].selection == selection && candidates[i].rr_depth == default_start)
        return shared_variance(pilots[i]);
    return shared_variance(pilots.front());  // not reached: a selection's default start comes first
  };
  const PilotSums& base = pilots.front();
  const double v0 = shared_variance(base);
  const double v1 = std::max(base.branch_variance, 0.0);
  choice.shared_cost = base.shared_cost;
  choice.branch_cost = base.branch_cost;
  choice.shared_variance = v0 + v1 > 0.0 ? v0 / (v0 + v1) : 1.0;
  choice.optimum =
      base.branch_cost > 0.0 ? std::sqrt((v1 / v0) * (base.shared_cost / base.branch_cost)) : 1.0;
  // The least time to an error over the counts and the candidates; a candidate other than the defaults must
  // win by kChoiceMargin, since its estimate is noisier than the default's, which the render would otherwise
  // use.
  const auto best_count = [&](double shared, const PilotSums& p) {
    int best = counts.front();
    for (const int k : counts)
      if (time_to_error(k, shared, p) < time_to_error(best, shared, p)) best = k;
    return best;
  };
  choice.branches = best_count(v0, base);
  double best_time = time_to_error(choice.branches, v0, base);
  for (size_t i = 1; i < candidates.size(); ++i) {
    const double shared = v0_of(candidates[i].selection);
    const int k = best_count(shared, pilots[i]);
    const double t = time_to_error(k, shared, pilots[i]);
    if (t < kChoiceMargin * best_time) {
      best_time = t;
      choice.branches = k;
      choice.rr_depth = candidates[i].rr_depth;
      choice.light_selection = candidates[i].selection;
    }
  }
  const double one_path = time_to_error(counts.front(), v0, base);
  choice.predicted_gain = best_time > 0.0 ? one_path / best_time : 1.0;
  choice.reason = fmt::format(
      "{} branch{}, roulette from depth {}{} (pilot {:.2f} s: the shared part at most {:.1f} % of the "
      "variance, "
      "{:.2f} against {:.2f} rays a continuation, best count {:.1f}; predicted {:.2f}x less time to an "
      "error)",
      choice.branches, choice.branches == 1 ? "" : "es", choice.rr_depth, lights_phrase(scene, choice),
      choice.seconds, 100.0 * choice.shared_variance, choice.shared_cost, choice.branch_cost, choice.optimum,
      choice.predicted_gain);
  return choice;
}

RenderJob resolve_branches(const Scene& scene, RenderJob job, BranchChoice* choice) {
  RenderSettings& s = job.settings;
  if (!has_automatic_choices(s)) return job;
  // The guide first, from the whole render's settings (guide_training.h): the pilot then weighs its
  // choices with the guided paths the render will trace.
  GuideTraining training;
  if (needs_guide(s)) s.guide = train_path_guide(scene, job, &training);
  if (choice) choice->guide = training;
  if (s.guiding == GuidingSetting::kOn && !s.guide) s.guiding = GuidingSetting::kOff;  // nothing learned
  if (!has_automatic_choices(s)) return job;
  BranchChoice chosen = choose_branches(scene, job);
  chosen.guide = training;
  s.roulette_chosen = s.rr_depth == RenderSettings::kAutoRoulette;
  s.rr_depth = chosen.rr_depth;
  s.light_selection_chosen = s.light_selection == LightSelection::kAuto;
  s.light_selection = chosen.light_selection;
  if (choice) *choice = chosen;
  if (s.branches != RenderSettings::kAutoBranches) return job;
  const uint32_t k = static_cast<uint32_t>(chosen.branches);
  if (s.spp % k != 0 || s.sample_begin % k != 0)
    throw std::invalid_argument(
        fmt::format("resolve_branches: samples [{}, {}) are not whole camera samples of {}", s.sample_begin,
                    s.sample_begin + s.spp, k));
  s.branches = chosen.branches;
  s.spp /= k;
  s.sample_begin /= k;
  s.branches_chosen = true;
  return job;
}

}  // namespace ochre
