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
// The pilot runs only where the render traces at least this many times the pilot's paths.
constexpr double kMinRenderToPilot = 20.0;
constexpr int kMaxAutoBranches = 16;
constexpr double kUncertainties = 1.0;     // how far above its estimate V0 is taken
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

template <class Sampler>
PixelPilot pilot_pixel(const Scene& scene, const RenderSettings& s, const PathIntegrator& integrator,
                       const GridPixel& pixel) {
  thread_local LobeArena arena;
  const RayCone cone = scene.camera.pixel_cone();
  const SensorResponse* sensor = scene.sensor.get();
  std::array<std::array<double, kPilotSamples>, 3> estimate{}, spread{};  // per channel and sample
  PixelPilot out;
  for (uint32_t i = 0; i < kPilotSamples; ++i) {
    const auto [sampler, lambda, ray] =
        camera_sample<Sampler>(scene, kPilotSeed, pixel.x, pixel.y, s.width, i);
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

// Time to a given error with k continuations, relative to one: (V0 + V1 / k)(c0 + k c1) / ((V0 + V1)(c0 +
// c1)).
double relative_time(double k, double v0, double v1, double c0, double c1) {
  return (v0 + v1 / k) * (c0 + k * c1) / ((v0 + v1) * (c0 + c1));
}

}  // namespace

BranchChoice choose_branches(const Scene& scene, const RenderJob& job) {
  const RenderSettings& s = job.settings;
  BranchChoice choice;
  if (s.noise_threshold > 0.0) {
    choice.reason = "1 (a noise-threshold render decides per pixel from its camera samples)";
    return choice;
  }
  // A power of two dividing spp (and sample_begin) that leaves kMinCameraSamples camera samples.
  uint32_t cap = std::min<uint32_t>(kMaxAutoBranches, s.spp / kMinCameraSamples);
  cap = std::min(cap, power_of_two_dividing(s.spp));
  if (s.sample_begin > 0) cap = std::min(cap, power_of_two_dividing(s.sample_begin));
  if (cap < 2) {
    choice.reason =
        fmt::format("1 ({} paths per pixel: fewer than {} camera samples of 2)", s.spp, kMinCameraSamples);
    return choice;
  }
  const std::vector<GridPixel> grid = pilot_grid(s.width, s.height);
  const double render_paths = double(s.width) * s.height * s.spp;
  const double pilot_paths = 2.0 * kPilotSamples * grid.size();
  if (render_paths < kMinRenderToPilot * pilot_paths) {
    choice.reason = fmt::format("1 (a render of {:.3g} paths is too small for the pilot)", render_paths);
    return choice;
  }

  const auto start = std::chrono::steady_clock::now();
  RenderSettings pilot_settings = s;
  pilot_settings.branches = 2;
  const PathIntegrator integrator(scene, pilot_settings, polarization_for(scene, job).mode);
  std::vector<PixelPilot> pixels(grid.size());
  {
    const int threads = s.threads > 0 ? s.threads : tbb::this_task_arena::max_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(threads));
    // Independent numbers whatever the render's sampler: a stratified sampler's samples and branches are
    // anti-correlated (the two branches of a Sobol sample fall in opposite halves of every dimension), which
    // would bias the variance estimates.
    tbb::parallel_for(size_t(0), grid.size(), [&](size_t i) {
      pixels[i] = pilot_pixel<IndependentSampler>(scene, s, integrator, grid[i]);
    });
  }
  // Summed in pixel order: the same figures for any thread count.
  PixelPilot sum;
  for (const PixelPilot& p : pixels) {
    sum.shared_variance += p.shared_variance;
    sum.branch_variance += p.branch_variance;
    sum.shared_cost += p.shared_cost;
    sum.branch_cost += p.branch_cost;
  }
  // V0 is a small difference of noisy estimates where the shared part is nearly noise-free: it is taken at
  // the upper end of its uncertainty (the pixels' spread, an upper bound of their noise), which errs towards
  // fewer branches, the cheaper mistake.
  const double mean_shared = sum.shared_variance / double(pixels.size());
  double spread = 0;
  for (const PixelPilot& p : pixels)
    spread += (p.shared_variance - mean_shared) * (p.shared_variance - mean_shared);
  const double shared_uncertainty = std::sqrt(spread);
  sum.shared_variance = std::max(sum.shared_variance, 0.0) + kUncertainties * shared_uncertainty;
  choice.piloted = true;
  choice.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double v1 = std::max(sum.branch_variance, 0.0);
  const double v0 = std::max(sum.shared_variance, 1e-6 * v1);
  const double c0 = sum.shared_cost, c1 = sum.branch_cost;
  choice.shared_cost = c0 / double(kPilotSamples * grid.size());
  choice.branch_cost = c1 / double(kPilotSamples * grid.size());
  choice.shared_variance = v0 + v1 > 0.0 ? v0 / (v0 + v1) : 1.0;
  if (!(v1 > 0.0) || !(c1 > 0.0)) {
    choice.reason = "1 (the continuations add no variance)";
    return choice;
  }
  choice.optimum = std::sqrt((v1 / v0) * (c0 / c1));
  // The power of two nearest the optimum (in ratio), within the cap.
  int k = 1;
  while (k * 2 <= static_cast<int>(cap) && choice.optimum >= k * std::sqrt(2.0)) k *= 2;
  choice.branches = k;
  choice.predicted_gain = 1.0 / relative_time(k, v0, v1, c0, c1);
  choice.reason = fmt::format(
      "{} (pilot {:.2f} s: the shared part at most {:.1f} % of the variance, {:.2f} against {:.2f} rays a "
      "continuation; "
      "best {:.1f}, predicted {:.2f}x less time to an error)",
      k, choice.seconds, 100.0 * choice.shared_variance, choice.shared_cost, choice.branch_cost,
      choice.optimum, choice.predicted_gain);
  return choice;
}

RenderJob resolve_branches(const Scene& scene, RenderJob job, BranchChoice* choice) {
  RenderSettings& s = job.settings;
  if (s.branches != RenderSettings::kAutoBranches) return job;
  const BranchChoice chosen = choose_branches(scene, job);
  const uint32_t k = static_cast<uint32_t>(chosen.branches);
  if (s.spp % k != 0 || s.sample_begin % k != 0)
    throw std::invalid_argument(
        fmt::format("resolve_branches: samples [{}, {}) are not whole camera samples of {}", s.sample_begin,
                    s.sample_begin + s.spp, k));
  s.branches = chosen.branches;
  s.spp /= k;
  s.sample_begin /= k;
  s.branches_chosen = true;
  if (choice) *choice = chosen;
  return job;
}

}  // namespace ochre
