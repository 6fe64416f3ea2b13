// ochre-bench: renderer throughput against raw Embree on the same triangles (docs/tools.md).
//   ochre-bench [SCENE.json ...] [--spp N] [--threads N] [--seconds S] [--repeat N]
//   ochre-bench --modes [SCENE.json ...] [--repeat N]
// For each scene: renders it (samples/s, rays/s counting intersect and occlusion queries), then traces
// random incoherent rays through an Embree BVH of the same meshes, built with the renderer's options (robust,
// high quality) and with Embree's defaults (tools/bench/raw_embree_benchmark.h)
// and prints renderer rays/s / raw rays/s: the median and range over N interleaved rounds. With --modes:
// renders each scene in polarization modes off, intensity and stokes (interleaved, N times), prints the
// median time per sample of each as a ratio to off (goals: intensity <= 1.3x, stokes <= 2x) and the
// difference mode off makes to the mean luminance. Exit codes (docs/cli.md, "Exit codes"): 0 = done, 2 = bad
// input or usage, 1 = internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ochre/version.h"
#include "renderer/film/film.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/scene/polarization_mode.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/bench/raw_embree_benchmark.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"
#include "tools/cli/tool_files.h"

namespace {

namespace fs = std::filesystem;

// The goal of docs/performance.md: the renderer keeps at least half of raw Embree's rate.
constexpr double kGoalRatio = 0.5;

struct BenchCommand {
  std::vector<std::string> scenes;
  std::optional<uint32_t> spp;
  int threads = 0;
  double seconds = 2.0;
  uint64_t seed = 1;
  bool modes = false;
  int repeat = 3;
};

// An example scene of scenes/ (installed with the tools, else in the source tree; tools/cli/tool_files.h).
std::string example_scene(const fs::path& relative) {
  return ochre::tool_file("scenes" / relative, "scenes" / relative).string();
}

std::vector<std::string> default_scenes() {
  return {example_scene("default/default.json"), example_scene("cornell-box/cornell-box.json")};
}

// The scene the mode costs are measured on: the Cornell box with a gold and a glass sphere.
std::string polarized_scene() {
  return example_scene("cornell-box/cornell-box-polarized.json");
}

std::string rate(double per_second) {
  if (per_second >= 1e6) return fmt::format("{:.2f} M/s", per_second / 1e6);
  return fmt::format("{:.1f} k/s", per_second / 1e3);
}

void print_raw(const char* what, const ochre::RawEmbreeResult& raw) {
  fmt::print("  {}: {:.3f} s on {} threads, {} rays/s ({} rays, {:.1f} % hit; BVH build {:.3f} s)\n", what,
             raw.seconds, raw.threads, rate(raw.rays_per_second()), raw.rays,
             raw.rays ? 100.0 * raw.hits / raw.rays : 0.0, raw.build_seconds);
}

// Renders once more with the Accel timing its Embree queries: the share of the render's thread time spent
// in traversal, the renderer's Embree cost per ray, and the ratio the renderer would reach if everything but
// traversal were free (its own rays, traced at their own cost).
void report_traversal_share(ochre::Scene& scene, const ochre::RenderJob& job,
                            const ochre::RawEmbreeResult& raw) {
  ochre::Film film(job.settings.width, job.settings.height);
  scene.accel->set_traversal_timing(true);
  const ochre::RenderStats stats = ochre::render(scene, job, film);
  const double traversal = scene.accel->traversal_seconds();
  scene.accel->set_traversal_timing(false);
  const double thread_seconds = stats.seconds * stats.threads;
  const uint64_t rays = stats.rays + stats.shadow_rays;
  if (!(traversal > 0.0) || rays == 0 || !(raw.rays_per_second() > 0.0)) return;
  const double ceiling = static_cast<double>(rays) * stats.threads / traversal / raw.rays_per_second();
  fmt::print(
      "  traversal (timed render, {:.3f} s): {:.1f} % of thread time in Embree queries, {:.0f} ns per "
      "renderer "
      "ray (raw: {:.0f} ns); with free shading the ratio would be {:.0f} %\n",
      stats.seconds, 100.0 * traversal / thread_seconds, 1e9 * traversal / static_cast<double>(rays),
      1e9 * raw.threads / raw.rays_per_second(), 100.0 * ceiling);
}

// Median and range of a set of measurements.
struct Spread {
  double median = 0, min = 0, max = 0;
};
Spread spread(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v.front(), v.back()};
}

// Returns the median renderer / raw ratio of one scene over --repeat rounds. Each round renders the scene
// and then traces the raw rays, so a change in the machine's load hits both halves of its ratio.
double bench_scene(const BenchCommand& cmd, const std::string& file) {
  ochre::SceneOverrides overrides;
  overrides.spp = cmd.spp;
  if (cmd.threads > 0) overrides.threads = cmd.threads;
  const ochre::LoadedScene loaded = ochre::load_scene(file, overrides);
  const std::unique_ptr<ochre::Scene>& scene = loaded.scene;
  const ochre::RenderSettings& settings = loaded.job.settings;
  size_t triangles = 0;
  for (const ochre::Mesh& mesh : scene->meshes) triangles += mesh.triangle_count();
  if (triangles == 0)
    throw ochre::InputError(file + ": the scene has no triangle to trace (ochre-bench compares ray rates)");
  fmt::print("{}: {} meshes, {} triangles, {}x{} at {} spp, {} round(s)\n", file, scene->meshes.size(),
             triangles, settings.width, settings.height, settings.spp, cmd.repeat);
  std::fflush(stdout);

  std::vector<double> ratios, renderer_rates, raw_rates;
  ochre::RawEmbreeResult raw;
  for (int round = 0; round < cmd.repeat; ++round) {
    ochre::Film film(settings.width, settings.height);
    const ochre::RenderStats stats = ochre::render(*scene, loaded.job, film);
    fmt::print("  renderer:  {:.3f} s on {} threads, {} samples/s, {} rays/s ({} intersect + {} occlusion)\n",
               stats.seconds, stats.threads, rate(stats.samples_per_second()), rate(stats.rays_per_second()),
               stats.rays, stats.shadow_rays);
    std::fflush(stdout);
    // Yardstick: the same triangles in a BVH built with the renderer's options (robust, high quality).
    raw = ochre::benchmark_raw_embree(scene->meshes, stats.threads, cmd.seconds, cmd.seed, {true, true});
    print_raw("raw Embree (renderer's BVH options: robust, high quality)", raw);
    renderer_rates.push_back(stats.rays_per_second());
    raw_rates.push_back(raw.rays_per_second());
    ratios.push_back(raw.rays_per_second() > 0 ? stats.rays_per_second() / raw.rays_per_second() : 0.0);
    std::fflush(stdout);
  }
  // Embree's default options, once, to show what robust mode costs.
  const ochre::RawEmbreeResult plain =
      ochre::benchmark_raw_embree(scene->meshes, raw.threads, cmd.seconds, cmd.seed, {false, false});
  print_raw("raw Embree (Embree's default options)", plain);
  const Spread ratio = spread(ratios), renderer_rate = spread(renderer_rates), raw_rate = spread(raw_rates);
  const double plain_ratio =
      plain.rays_per_second() > 0 ? renderer_rate.median / plain.rays_per_second() : 0.0;
  if (cmd.repeat > 1)
    fmt::print("  median of {} rounds: renderer {} rays/s ({} .. {}), raw {} rays/s ({} .. {})\n", cmd.repeat,
               rate(renderer_rate.median), rate(renderer_rate.min), rate(renderer_rate.max),
               rate(raw_rate.median), rate(raw_rate.min), rate(raw_rate.max));
  fmt::print(
      "  ratio renderer/raw rays/s: {:.1f} % (range {:.1f} .. {:.1f} %; goal >= {:.0f} %){}; against "
      "Embree's "
      "defaults {:.1f} %\n",
      100.0 * ratio.median, 100.0 * ratio.min, 100.0 * ratio.max, 100.0 * kGoalRatio,
      ratio.median >= kGoalRatio ? "" : "  BELOW GOAL", 100.0 * plain_ratio);
  report_traversal_share(*scene, loaded.job, raw);
  return ratio.median;
}

// Mean luminance (Y) of a film.
double mean_luminance(const ochre::Film& film) {
  double sum = 0.0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) sum += film.mean(x, y).y;
  return sum / (static_cast<double>(film.width()) * film.height());
}

// Time per sample of the three polarization modes, and mode off's luminance against mode intensity's.
void bench_modes(const BenchCommand& cmd, const std::string& file) {
  const std::array<const char*, 3> modes = {"off", "intensity", "stokes"};
  std::array<ochre::LoadedScene, 3> scenes;
  for (size_t m = 0; m < modes.size(); ++m) {
    ochre::SceneOverrides overrides;
    overrides.spp = cmd.spp;
    if (cmd.threads > 0) overrides.threads = cmd.threads;
    overrides.polarization = ochre::kPolarizationSettings.parse(modes[m]);
    scenes[m] = ochre::load_scene(file, overrides);
    scenes[m].job.outputs.stokes = m == 2;
  }
  const ochre::RenderSettings& s = scenes[0].job.settings;
  fmt::print("{}: polarization modes, {}x{} at {} spp, {} repetitions (interleaved)\n", file, s.width,
             s.height, s.spp, cmd.repeat);
  std::array<std::vector<double>, 3> ns_per_sample;
  std::array<double, 3> luminance{};
  for (int r = 0; r < cmd.repeat; ++r)
    for (size_t m = 0; m < modes.size(); ++m) {
      ochre::Film film(s.width, s.height);
      if (m == 2) film.enable_stokes();
      const ochre::RenderStats stats = ochre::render(*scenes[m].scene, scenes[m].job, film);
      ns_per_sample[m].push_back(1e9 * stats.seconds / static_cast<double>(stats.samples));
      luminance[m] = mean_luminance(film);
    }
  std::array<Spread, 3> time{};
  for (size_t m = 0; m < modes.size(); ++m) time[m] = spread(ns_per_sample[m]);
  const std::array<double, 3> goal = {1.0, 1.3, 2.0};
  for (size_t m = 0; m < modes.size(); ++m)
    fmt::print("  {:<9}  {:8.1f} ns/sample (min {:.1f}, max {:.1f})  {:.2f}x off{}  mean Y {:.6f}\n",
               modes[m], time[m].median, time[m].min, time[m].max, time[m].median / time[0].median,
               m == 0 ? ""
                      : fmt::format(" (goal <= {:.1f}x){}", goal[m],
                                    time[m].median / time[0].median <= goal[m] ? "" : "  ABOVE GOAL"),
               luminance[m]);
  fmt::print("  mode off vs intensity: mean luminance {:+.2f} % (Monte-Carlo noise included)\n",
             100.0 * (luminance[0] / luminance[1] - 1.0));
}

int bench_command(int argc, char** argv) {
  CLI::App app{"ochre-bench: renderer rays/s against raw Embree rays/s on the same geometry"};
  app.set_version_flag("--version", "ochre-bench " OCHRE_VERSION);
  BenchCommand cmd;
  uint32_t spp = 0;
  app.add_option("scenes", cmd.scenes, "Scenes (JSON; default scenes/default and scenes/cornell-box)");
  auto* spp_opt =
      app.add_option("--spp", spp, "Samples per pixel (default: the scene's)")->check(CLI::PositiveNumber);
  app.add_option("--threads", cmd.threads, "Threads for both (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--seconds", cmd.seconds, "Minimum duration of the raw Embree run (default 2)")
      ->check(ochre::finite_positive());
  app.add_option("--seed", cmd.seed, "Seed of the raw Embree rays")->check(ochre::unsigned_64_check());
  app.add_flag("--modes", cmd.modes, "Time the polarization modes off / intensity / stokes instead");
  app.add_option("--repeat", cmd.repeat,
                 "Rounds per scene (render + raw Embree), or per mode with --modes; medians are reported "
                 "(default 3)")
      ->check(CLI::PositiveNumber);
  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  if (*spp_opt) cmd.spp = spp;
  if (cmd.scenes.empty())
    cmd.scenes = cmd.modes ? std::vector<std::string>{polarized_scene()} : default_scenes();
  ochre::install_signal_cleanup();  // loading a textured scene writes converted textures to the cache
  for (const std::string& scene : cmd.scenes) {
    if (cmd.modes)
      bench_modes(cmd, scene);
    else
      bench_scene(cmd, scene);
  }
  return ochre::kExitDone;
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-bench", [&] { return bench_command(argc, argv); });
}
