// ochre-converge: error against render time (docs/tools.md).
//   ochre-converge SCENE.json --reference REF.exr|auto --spp 1,4,16 [--variant NAME:key=value,...]...
//                  [--csv OUT.csv] [--plot OUT.png] [--threads N] [--seed S] [--width W --height H]
// Renders the scene at each sample count for each variant, times each render (scene loading excluded)
// and compares the image with the reference (relative MSE and RMSE, renderer/compare/image_metrics.h).
// Exit codes (docs/cli.md, "Exit codes"): 0 = done, 2 = bad input or usage, 1 = internal error.
#include <fmt/format.h>

#include <charconv>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ochre/version.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/film/film.h"
#include "renderer/image/exr_reader.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/output/output_files.h"
#include "renderer/output/render_output.h"
#include "renderer/scene/render_settings.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"
#include "tools/cli/python_script.h"

namespace {

namespace fs = std::filesystem;
using ochre::InputError;

// The reference is rendered with this many times the largest sample count when asked for "auto".
constexpr uint32_t kAutoReferenceFactor = 16;
// Added to the seed of an automatic reference so that its noise is independent of the variants'.
constexpr uint64_t kReferenceSeedOffset = 1000003;

struct Variant {
  std::string name;
  ochre::SceneOverrides overrides;
};

struct ConvergeCommand {
  std::string scene, reference, csv, plot;
  std::vector<uint32_t> spp;
  std::vector<std::string> variant_specs;
  std::optional<int> threads, width, height;
  std::optional<uint64_t> seed;
};

struct Row {
  std::string variant;
  uint32_t spp = 0;
  double seconds = 0, relmse = 0, rmse = 0;
};

// Applies one "key=value" of a --variant to its overrides (the keys SceneOverrides supports, except
// spp, which --spp sweeps).
void apply_variant_setting(const std::string& spec, const std::string& key, const std::string& value,
                           ochre::SceneOverrides& o) {
  const auto number = [&](auto& target) {
    try {
      size_t used = 0;
      const long long v = std::stoll(value, &used);
      using Target = std::decay_t<decltype(*target)>;
      // Checked before the conversion: 4294967297 must not wrap to 1.
      if (used != value.size() || v < 0 ||
          static_cast<unsigned long long>(v) > std::numeric_limits<Target>::max())
        throw std::invalid_argument(value);
      target = static_cast<Target>(v);
    } catch (const std::logic_error&) {
      throw InputError(fmt::format("--variant '{}': {} must be a non-negative integer in range, not '{}'",
                                   spec, key, value));
    }
  };
  // A choice value: its enum, or an error naming the variant, the setting and the known values.
  const auto choice = [&](const auto& choices) {
    const auto parsed = choices.parse(value);
    if (!parsed)
      throw InputError(
          fmt::format("--variant '{}': unknown {} '{}' (known: {})", spec, key, value, choices.list()));
    return *parsed;
  };
  if (key == "sampler")
    o.sampler = choice(ochre::kSamplerKinds);
  else if (key == "seed")
    number(o.seed);
  else if (key == "threads")
    number(o.threads);
  else if (key == "width")
    number(o.width);
  else if (key == "height")
    number(o.height);
  else if (key == "polarization")
    o.polarization = choice(ochre::kPolarizationSettings);
  else if (key == "branches") {
    number(o.branches);
    if (*o.branches < 1 || *o.branches > ochre::RenderSettings::kMaxBranches)
      throw InputError(fmt::format("--variant '{}': branches must be in [1, {}], not {}", spec,
                                   ochre::RenderSettings::kMaxBranches, *o.branches));
  } else if (key == "noise_threshold") {
    // As --noise-threshold: a finite number in [0, 1], the whole value.
    double threshold = -1.0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), threshold);
    if (error != std::errc() || end != value.data() + value.size() || !(threshold >= 0.0 && threshold <= 1.0))
      throw InputError(
          fmt::format("--variant '{}': noise_threshold must be a number in [0, 1], not '{}'", spec, value));
    o.noise_threshold = threshold;
  } else if (key == "spp")
    throw InputError(fmt::format("--variant '{}': spp is swept by --spp, not set per variant", spec));
  else
    throw InputError(
        fmt::format("--variant '{}': unknown setting '{}' (sampler, seed, threads, width, height, "
                    "polarization, branches, noise_threshold)",
                    spec, key));
}

// "NAME:key=value,key=value" (or just "NAME" for the scene's own settings).
Variant parse_variant(const std::string& spec, const ochre::SceneOverrides& base) {
  Variant v{spec.substr(0, spec.find(':')), base};
  if (v.name.empty() || v.name.find(',') != std::string::npos)
    throw InputError(
        fmt::format("--variant '{}': expected NAME:key=value,... with a name and no comma in it", spec));
  if (spec.find(':') == std::string::npos) return v;
  std::string rest = spec.substr(spec.find(':') + 1);
  size_t start = 0;
  while (start <= rest.size()) {
    const size_t end = std::min(rest.find(',', start), rest.size());
    const std::string item = rest.substr(start, end - start);
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(fmt::format("--variant '{}': '{}' is not key=value", spec, item));
    apply_variant_setting(spec, item.substr(0, eq), item.substr(eq + 1), v.overrides);
    start = end + 1;
  }
  return v;
}

ochre::SceneOverrides base_overrides(const ConvergeCommand& cmd) {
  ochre::SceneOverrides o;
  o.threads = cmd.threads;
  o.seed = cmd.seed;
  o.width = cmd.width;
  o.height = cmd.height;
  return o;
}

// Renders `scene` at `spp` samples per pixel; returns the linear RGB image and the wall-clock seconds.
ochre::RgbImage render_image(ochre::LoadedScene& loaded, uint32_t spp, double* seconds) {
  ochre::RenderJob& job = loaded.job;
  job.settings.spp = spp;
  job.settings.sample_begin = 0;
  ochre::Film film(job.settings.width, job.settings.height);
  const ochre::RenderStats stats = ochre::render(*loaded.scene, job, film);
  if (seconds) *seconds = stats.seconds;
  return {film.width(), film.height(), ochre::film_to_rgb(film, job.outputs),
          ochre::kWorkingSpaces.name(job.outputs.colorspace)};
}

ochre::RgbImage auto_reference(const ConvergeCommand& cmd) {
  ochre::SceneOverrides o = base_overrides(cmd);
  ochre::LoadedScene loaded = ochre::load_scene(cmd.scene, o);
  ochre::RenderSettings& settings = loaded.job.settings;
  const uint32_t spp = kAutoReferenceFactor * *std::max_element(cmd.spp.begin(), cmd.spp.end());
  const uint64_t seed = settings.seed + kReferenceSeedOffset;
  settings.seed = seed;
  settings.noise_threshold = 0.0;  // every pixel at the reference's samples
  fmt::print("reference: auto, rendered here at {} spp ({}x the largest) with seed {} (sampler {}, {}x{})\n",
             spp, kAutoReferenceFactor, seed, ochre::kSamplerKinds.name(settings.sampler), settings.width,
             settings.height);
  double seconds = 0;
  ochre::RgbImage image = render_image(loaded, spp, &seconds);
  fmt::print("reference: {:.3f} s\n", seconds);
  return image;
}

ochre::DisplayOptions no_ocio() {
  ochre::DisplayOptions options;
  options.ocio_config = "none";
  return options;
}

std::vector<Row> run_variant(const ConvergeCommand& cmd, const Variant& variant,
                             const ochre::RgbImage& reference) {
  ochre::LoadedScene loaded = ochre::load_scene(cmd.scene, variant.overrides);
  std::vector<Row> rows;
  for (uint32_t spp : cmd.spp) {
    Row row{variant.name, spp};
    const ochre::RgbImage image = render_image(loaded, spp, &row.seconds);
    ochre::check_comparable(image, reference,
                            fmt::format("{} (variant {}, {} spp)", cmd.scene, variant.name, spp),
                            cmd.reference);
    const ochre::ImageMetrics m = ochre::compare_images(image, reference, no_ocio()).metrics;
    row.relmse = m.relmse;
    row.rmse = m.rmse;
    fmt::print("  {:<14} {:>7} {:>11.4f} {:>12.5g} {:>12.5g} {:>16.5g}\n", row.variant, row.spp, row.seconds,
               row.relmse, row.rmse, row.relmse * row.seconds);
    std::fflush(stdout);
    rows.push_back(row);
  }
  return rows;
}

void write_csv(const ochre::AtomicOutput& output, const std::vector<Row>& rows) {
  std::string csv = "variant,spp,seconds,relmse,rmse,relmse_x_seconds\n";
  for (const Row& r : rows)
    csv += fmt::format("{},{},{:.9g},{:.9g},{:.9g},{:.9g}\n", r.variant, r.spp, r.seconds, r.relmse, r.rmse,
                       r.relmse * r.seconds);
  ochre::write_text_file(output, csv);
}

// log(relMSE) at log(seconds), linear between the variant's rows sorted by time; nullopt outside.
std::optional<double> log_relmse_at(std::vector<Row> rows, double log_t) {
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.seconds < b.seconds; });
  for (size_t i = 0; i + 1 < rows.size(); ++i) {
    const double t0 = std::log(rows[i].seconds), t1 = std::log(rows[i + 1].seconds);
    if (log_t < t0 || log_t > t1) continue;
    const double w = t1 > t0 ? (log_t - t0) / (t1 - t0) : 0.0;
    return (1 - w) * std::log(rows[i].relmse) + w * std::log(rows[i + 1].relmse);
  }
  return std::nullopt;
}

// Prints, for each variant after the first, relMSE(variant) / relMSE(first) at equal render time,
// interpolated in log-log at each of the first variant's times that both curves cover.
void print_equal_time_ratios(const std::vector<std::vector<Row>>& by_variant) {
  const std::vector<Row>& base = by_variant.front();
  for (size_t v = 1; v < by_variant.size(); ++v) {
    std::vector<std::string> points;
    double log_sum = 0;
    int count = 0;
    for (const Row& b : base) {
      const auto other = log_relmse_at(by_variant[v], std::log(b.seconds));
      if (!other) continue;
      const double ratio = std::exp(*other - std::log(b.relmse));
      points.push_back(fmt::format("{:.3f}@{:.3g}s", ratio, b.seconds));
      log_sum += std::log(ratio);
      ++count;
    }
    if (count == 0) {
      fmt::print("equal-time error ratio {}/{}: the time ranges do not overlap\n",
                 by_variant[v].front().variant, base.front().variant);
      continue;
    }
    fmt::print("equal-time error ratio relMSE({}) / relMSE({}): geometric mean {:.3f} ({})\n",
               by_variant[v].front().variant, base.front().variant, std::exp(log_sum / count),
               fmt::join(points, ", "));
  }
}

// Runs the plotting script on the CSV's temporary into the PNG's; a missing Python or matplotlib is a
// warning (the CSV is still written). Returns whether the plot was made.
bool plot(const ochre::AtomicOutput& csv, const ochre::AtomicOutput& png) {
  const fs::path script = ochre::tool_script("plot_convergence.py");
  if (ochre::run_python(script, {csv.temp_path().string(), png.temp_path().string()})) return true;
  fmt::print(stderr,
             "ochre-converge: warning: plot {} not written ({} failed; is matplotlib installed?); "
             "the CSV {} is kept\n",
             png.final_path().string(), script.string(), csv.final_path().string());
  return false;
}

// The CSV and the plot, together (the plot only when the script succeeds).
void write_results(const ConvergeCommand& cmd, const std::vector<Row>& rows,
                   const ochre::InputFileLog& inputs) {
  std::vector<fs::path> outputs = {cmd.csv};
  if (!cmd.plot.empty()) outputs.emplace_back(cmd.plot);
  ochre::check_output_files(outputs, inputs);  // again: the scene's own files are known now
  ochre::OutputTransaction transaction;
  ochre::AtomicOutput& csv = transaction.add(cmd.csv);
  write_csv(csv, rows);
  bool plotted = false;
  if (!cmd.plot.empty()) {
    auto png = std::make_unique<ochre::AtomicOutput>(cmd.plot);
    plotted = plot(csv, *png);
    if (plotted) transaction.add(std::move(png));
  }
  transaction.commit();
  fmt::print("csv: {}\n", cmd.csv);
  if (plotted) fmt::print("plot: {}\n", cmd.plot);
}

int run_converge(ConvergeCommand cmd) {
  if (cmd.spp.empty()) throw InputError("--spp: give at least one sample count");
  if (std::find(cmd.spp.begin(), cmd.spp.end(), 0u) != cmd.spp.end())
    throw InputError("--spp: counts must be > 0");
  const ochre::SceneOverrides base = base_overrides(cmd);
  std::vector<Variant> variants;
  for (const std::string& spec : cmd.variant_specs) variants.push_back(parse_variant(spec, base));
  if (variants.empty()) variants.push_back({"base", base});

  // A plot needs a CSV: without --csv it goes beside the PNG.
  if (!cmd.plot.empty() && cmd.csv.empty()) cmd.csv = fs::path(cmd.plot).replace_extension(".csv").string();

  if (cmd.reference != "auto" && !fs::exists(cmd.reference))
    throw InputError(fmt::format("--reference {}: no such file", cmd.reference));
  // Every file the run reads (the scene and its files, the reference), so that no output replaces one.
  ochre::InputFileLog inputs;
  const ochre::InputFileLog::Recording recording(inputs);
  ochre::check_regular_input(cmd.scene, ochre::kSceneFileInput);
  if (cmd.reference != "auto") ochre::check_regular_input(cmd.reference, ochre::kImageFileInput);
  // The plot first: when the CSV is the one derived from it, a bad directory is reported under the name
  // given.
  std::vector<fs::path> outputs;
  if (!cmd.plot.empty()) outputs.emplace_back(cmd.plot);
  if (!cmd.csv.empty()) outputs.emplace_back(cmd.csv);
  ochre::check_output_files(outputs, inputs);  // before any render
  const ochre::RgbImage reference = cmd.reference == "auto"
                                        ? auto_reference(cmd)
                                        : ochre::rgb_from_exr(ochre::read_exr(cmd.reference), cmd.reference);

  fmt::print("  {:<14} {:>7} {:>11} {:>12} {:>12} {:>16}\n", "variant", "spp", "seconds", "relmse", "rmse",
             "relmse*seconds");
  std::vector<std::vector<Row>> by_variant;
  std::vector<Row> rows;
  for (const Variant& variant : variants) {
    by_variant.push_back(run_variant(cmd, variant, reference));
    rows.insert(rows.end(), by_variant.back().begin(), by_variant.back().end());
  }
  if (by_variant.size() >= 2) print_equal_time_ratios(by_variant);
  if (!cmd.csv.empty()) write_results(cmd, rows, inputs);
  return ochre::kExitDone;
}

int converge_command(int argc, char** argv) {
  CLI::App app{"ochre-converge: relative MSE against render time, per variant of a scene's settings"};
  app.set_version_flag("--version", "ochre-converge " OCHRE_VERSION);
  ConvergeCommand cmd;
  int threads = 0, width = 0, height = 0;
  uint64_t seed = 0;
  app.add_option("scene", cmd.scene, "Scene (JSON)")->required();
  app.add_option("--reference", cmd.reference,
                 "Reference EXR, or 'auto' (rendered here at 16x the largest spp)")
      ->required()
      ->check(ochre::non_empty_path());
  app.add_option("--spp", cmd.spp, "Sample counts, e.g. 1,4,16,64")->delimiter(',')->required();
  app.add_option("--variant", cmd.variant_specs,
                 "NAME:key=value,... with keys sampler, seed, threads, width, height, polarization, branches, "
                 "noise_threshold (--spp is then the most a pixel takes) "
                 "(repeatable; default one variant 'base')");
  app.add_option("--csv", cmd.csv, "Write the rows variant,spp,seconds,relmse,rmse,relmse_x_seconds")
      ->check(ochre::non_empty_path());
  app.add_option("--plot", cmd.plot, "Write a log-log plot of relMSE against seconds (PNG, needs matplotlib)")
      ->check(ochre::non_empty_path());
  auto* threads_opt = app.add_option("--threads", threads, "Render threads (default: the scene's)")
                          ->check(CLI::Range(0, 4096));  // as ochre render
  auto* seed_opt =
      app.add_option("--seed", seed, "Seed (default: the scene's)")->check(ochre::unsigned_64_check());
  auto* width_opt =
      app.add_option("--width", width, "Film width (default: the scene's)")->check(CLI::PositiveNumber);
  auto* height_opt =
      app.add_option("--height", height, "Film height (default: the scene's)")->check(CLI::PositiveNumber);
  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  if (*threads_opt) cmd.threads = threads;
  if (*seed_opt) cmd.seed = seed;
  if (*width_opt) cmd.width = width;
  if (*height_opt) cmd.height = height;
  ochre::install_signal_cleanup();
  return run_converge(cmd);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-converge", [&] { return converge_command(argc, argv); });
}
