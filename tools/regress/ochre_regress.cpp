// ochre-regress: noise-aware image regression suite (docs/tools.md).
//   ochre-regress DIR [--update] [--junit OUT.xml] [--html REPORT_DIR [--history RUN ...]] [--spp N]
//                     [--reference-spp N] [--threads N]
// Renders every DIR/*.json scene and compares its luminance with DIR/references/<name>.exr by a per-pixel
// z-test with Sidak correction (renderer/compare/regression_compare.h); --html writes a report to look at
// (tools/regress/html_report.h).
// Exit codes (docs/cli.md, "Exit codes"): 0 = every scene passes, 4 = a scene fails, 2 = bad input or usage,
// 1 = internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ochre/version.h"
#include "renderer/compare/regression_compare.h"
#include "renderer/image/exr_reader.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/output/output_files.h"
#include "renderer/output/render_output.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"
#include "tools/regress/html_report.h"
#include "tools/regress/junit_report.h"
#include "tools/regress/report_history.h"

namespace fs = std::filesystem;

namespace {

// The reference of a scene is rendered with this offset added to the scene's seed, so that reference and
// test are independent estimates.
constexpr uint64_t kReferenceSeedOffset = 1000;
// Default reference sample count: this many times the scene's spp.
constexpr uint32_t kReferenceSppFactor = 16;

struct RegressCommand {
  std::string dir;
  bool update = false;
  std::string junit;
  std::optional<uint32_t> spp, reference_spp;
  std::optional<int> threads;
  std::vector<std::string> only;
  std::string output_dir = "regress-output";
  std::string html;
  std::vector<std::string> history;
};

struct SceneOutcome {
  std::string name;
  size_t pixels = 0;
  double worst_p = 1.0;
  size_t failing = 0;
  double seconds = 0.0;
  bool passed = true;
  std::string message;  // failure details
};

struct RenderedScene {
  std::unique_ptr<ochre::Film> film;
  ochre::OutputSettings outputs;  // working space and camera sensor (film_to_rgb)
  std::string description;
  uint32_t spp = 0;
  double seconds = 0.0;  // the render alone
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The film keeps the Stokes and spectral layers the scene's outputs ask for (an EXR path or not): the
// reference and the failing render's EXR carry them, and the HTML report shows them.
ochre::FilmLayers regress_film_layers(const ochre::OutputSettings& outputs) {
  ochre::FilmLayers layers = ochre::film_layers(outputs);
  layers.aovs = false;
  layers.spectral_bins = outputs.spectral_bins;
  return layers;
}

RenderedScene render_scene(const fs::path& file, uint32_t spp, uint64_t seed, std::optional<int> threads) {
  ochre::SceneOverrides overrides;
  overrides.spp = spp;
  overrides.seed = seed;
  overrides.threads = threads;
  const ochre::LoadedScene loaded = ochre::load_scene(file, overrides);
  const ochre::RenderJob& job = loaded.job;
  RenderedScene r;
  r.film = std::make_unique<ochre::Film>(job.settings.width, job.settings.height,
                                         regress_film_layers(job.outputs));
  const auto start = std::chrono::steady_clock::now();
  ochre::render(*loaded.scene, job, *r.film);
  r.seconds = seconds_since(start);
  r.outputs = job.outputs;
  r.description = loaded.scene->description;
  r.spp = spp;
  return r;
}

ochre::ExrImage rendered_image(const RenderedScene& r) {
  return ochre::make_reference_image(*r.film, ochre::film_to_rgb(*r.film, r.outputs), r.spp);
}

fs::path reference_path(const fs::path& dir, const std::string& name) {
  return dir / "references" / (name + ".exr");
}

std::vector<fs::path> scene_files(const RegressCommand& cmd) {
  const fs::path dir(cmd.dir);
  if (!fs::is_directory(dir)) throw ochre::InputError(cmd.dir + ": not a directory");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    // Not only regular files: a FIFO or a device named *.json is reported (spectra/input_file.h), not
    // skipped.
    if (!entry.is_directory() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (!cmd.only.empty()) {
    std::vector<fs::path> chosen;
    for (const std::string& name : cmd.only) {
      const fs::path file = dir / (name + ".json");
      if (std::find(files.begin(), files.end(), file) == files.end())
        throw ochre::InputError(cmd.dir + ": --scene " + name + ": no such scene (" + file.string() + ")");
      chosen.push_back(file);
    }
    files = chosen;
  }
  if (files.empty()) throw ochre::InputError(cmd.dir + ": no *.json scenes");
  return files;
}

// The scene's own spp and seed, read once without overrides.
ochre::RenderSettings scene_settings(const fs::path& file) {
  return ochre::load_scene(file).job.settings;
}

void update_reference(const RegressCommand& cmd, const fs::path& file, const ochre::InputFileLog& inputs) {
  const auto start = std::chrono::steady_clock::now();
  const ochre::RenderSettings settings = scene_settings(file);
  const fs::path out = reference_path(cmd.dir, file.stem().string());
  fs::create_directories(out.parent_path());
  ochre::check_output_files({out}, inputs);  // before the render: the scene and its files are read
  const uint32_t spp = cmd.reference_spp.value_or(kReferenceSppFactor * settings.spp);
  const RenderedScene r = render_scene(file, spp, kReferenceSeedOffset + settings.seed, cmd.threads);
  ochre::ExrImage image = rendered_image(r);
  image.string_attributes[ochre::kRenderSecondsAttribute] = fmt::format("{:.6f}", r.seconds);
  // write_exr goes through a temporary file and a rename: an interrupted update keeps the old reference.
  ochre::write_exr(out, image);
  const double seconds = seconds_since(start);
  fmt::print("updated {} ({} spp, seed {}, {:.2f} s)\n", out.string(), spp,
             kReferenceSeedOffset + settings.seed, seconds);
}

// What the HTML report shows of a scene.
ochre::SceneReport scene_report(const SceneOutcome& outcome, const RenderedScene& r,
                                ochre::RegressionResult result, ochre::ExrImage reference,
                                ochre::ExrImage render) {
  ochre::SceneReport report;
  report.name = outcome.name;
  report.description = r.description;
  report.message = outcome.message;
  report.result = std::move(result);
  report.reference = std::move(reference);
  report.render = std::move(render);
  report.working_space = ochre::kWorkingSpaces.name(r.outputs.colorspace);
  report.display = ochre::display_options(r.outputs);
  report.timing = {r.seconds, static_cast<double>(r.spp)};
  ochre::compare_scene_images(report);
  return report;
}

SceneOutcome run_scene(const RegressCommand& cmd, const fs::path& file, const ochre::InputFileLog& inputs,
                       ochre::HtmlReport* html) {
  const auto start = std::chrono::steady_clock::now();
  SceneOutcome outcome;
  outcome.name = file.stem().string();
  const fs::path ref_file = reference_path(cmd.dir, outcome.name);
  if (!fs::exists(ref_file))
    throw ochre::InputError(ref_file.string() + ": reference missing; create it with `ochre-regress " +
                            cmd.dir + " --update`");
  ochre::ExrImage reference_image = ochre::read_exr(ref_file);
  const ochre::LuminanceEstimate reference = ochre::luminance_from_reference(reference_image, ref_file);
  const ochre::RenderSettings settings = scene_settings(file);
  const RenderedScene r = render_scene(file, cmd.spp.value_or(settings.spp), settings.seed, cmd.threads);
  if (r.film->width() != reference.width || r.film->height() != reference.height)
    throw ochre::InputError(fmt::format(
        "{}: reference is {}x{} but the scene renders {}x{}; regenerate it "
        "with `ochre-regress {} --update`",
        ref_file.string(), reference.width, reference.height, r.film->width(), r.film->height(), cmd.dir));
  ochre::RegressionResult result = ochre::compare_luminance(ochre::luminance_from_film(*r.film), reference);
  outcome.pixels = result.p_values.size();
  outcome.worst_p = result.worst_p;
  outcome.failing = result.failing_pixels;
  outcome.passed = result.passed();
  if (!outcome.passed) {
    const fs::path out_dir(cmd.output_dir);
    fs::create_directories(out_dir);
    const fs::path render_exr = out_dir / (outcome.name + ".exr");
    const fs::path p_exr = out_dir / (outcome.name + ".pvalue.exr");
    const fs::path p_png = out_dir / (outcome.name + ".pvalue.png");
    std::vector<fs::path> outputs = {render_exr, p_exr, p_png};
    if (!cmd.junit.empty()) outputs.emplace_back(cmd.junit);
    ochre::check_output_files(outputs, inputs);
    ochre::OutputTransaction transaction;  // the three files of a failure, or none
    ochre::write_exr(transaction.add(render_exr), rendered_image(r));
    ochre::write_exr(transaction.add(p_exr), ochre::p_value_image(result));
    ochre::write_p_value_heatmap(transaction.add(p_png), result);
    transaction.commit();
    outcome.message = fmt::format(
        "{} of {} pixels below the per-pixel level {:.3g} (Sidak, alpha {}); worst p = {:.3g} at x={} y={} "
        "(z = {:.2f}); p-value image {}, heat map {}",
        result.failing_pixels, outcome.pixels, result.alpha_pixel, result.alpha, result.worst_p,
        result.worst_x, result.worst_y, result.z_scores[result.worst_y * result.width + result.worst_x],
        p_exr.string(), p_png.string());
  }
  outcome.seconds = seconds_since(start);  // the JUnit time: without writing the report
  if (html)
    html->add_scene(
        scene_report(outcome, r, std::move(result), std::move(reference_image), rendered_image(r)));
  return outcome;
}

ochre::RunRecord run_record(const std::vector<SceneOutcome>& outcomes, const std::string& timestamp) {
  ochre::RunRecord run;
  run.timestamp = timestamp;
  for (const auto& o : outcomes) run.scenes.push_back({o.name, o.passed, false, o.seconds, o.message});
  return run;
}

// The HTML report of the run, or nullptr without --html. Its destination and the history are checked
// before any rendering, so that a bad option fails at once and touches nothing.
std::unique_ptr<ochre::HtmlReport> open_html_report(const RegressCommand& cmd,
                                                    const std::vector<fs::path>& files,
                                                    const std::string& timestamp) {
  if (cmd.html.empty()) return nullptr;
  ochre::HtmlReport::check_destination(cmd.html, {cmd.junit, cmd.output_dir});
  std::vector<ochre::RunRecord> history = ochre::load_history(cmd.history);
  std::vector<std::string> names;
  for (const auto& file : files) names.push_back(file.stem().string());
  return std::make_unique<ochre::HtmlReport>(cmd.html, names, std::move(history),
                                             ochre::ReportHeading{cmd.dir, timestamp, OCHRE_VERSION});
}

int run(const RegressCommand& cmd) {
  const std::vector<fs::path> files = scene_files(cmd);
  // Every file the run reads (scenes, their meshes, textures, ..., references), so that no output
  // replaces one of them.
  ochre::InputFileLog inputs;
  const ochre::InputFileLog::Recording recording(inputs);
  for (const auto& file : files) ochre::check_regular_input(file, ochre::kSceneFileInput);
  if (cmd.update) {
    for (const auto& file : files) update_reference(cmd, file, inputs);
    return 0;
  }
  if (!cmd.junit.empty()) ochre::check_output_files({cmd.junit}, inputs);
  const std::string timestamp = ochre::utc_timestamp_now();
  const std::unique_ptr<ochre::HtmlReport> html = open_html_report(cmd, files, timestamp);
  std::vector<SceneOutcome> outcomes;
  for (const auto& file : files) outcomes.push_back(run_scene(cmd, file, inputs, html.get()));

  fmt::print("{:<28} {:>7} {:>10} {:>8} {:>8}  {}\n", "scene", "pixels", "worst p", "failing", "time",
             "result");
  bool all_passed = true;
  for (const auto& o : outcomes) {
    fmt::print("{:<28} {:>7} {:>10.3g} {:>8} {:>7.2f}s  {}\n", o.name, o.pixels, o.worst_p, o.failing,
               o.seconds, o.passed ? "PASS" : "FAIL");
    all_passed = all_passed && o.passed;
  }
  for (const auto& o : outcomes)
    if (!o.passed) fmt::print(stderr, "ochre-regress: {} FAILED: {}\n", o.name, o.message);
  const ochre::RunRecord run = run_record(outcomes, timestamp);
  if (!cmd.junit.empty()) {
    ochre::check_output_files({cmd.junit}, inputs);
    ochre::write_text_file(cmd.junit, ochre::junit_xml(run));
  }
  if (html) {
    const ochre::ReportStats stats = html->commit(run);
    fmt::print("HTML report: {} ({} files, {:.0f} KiB, written in {:.2f} s)\n",
               (fs::path(cmd.html) / "index.html").string(), stats.files,
               static_cast<double>(stats.bytes) / 1024.0, stats.seconds);
  }
  return all_passed ? ochre::kExitDone : ochre::kExitCheckFailed;
}

int regress_command(int argc, char** argv) {
  CLI::App app{
      "ochre-regress: noise-aware image regression tests (per-pixel luminance z-test, Sidak "
      "correction)"};
  app.set_version_flag("--version", "ochre-regress " OCHRE_VERSION);
  RegressCommand cmd;
  app.add_option("dir", cmd.dir, "Folder of *.json scenes with references/<name>.exr")->required();
  app.add_flag("--update", cmd.update,
               "Render the references (16 x the scene's spp, seed 1000 + scene seed)");
  app.add_option("--junit", cmd.junit, "Write a JUnit XML report")->check(ochre::non_empty_path());
  app.add_option("--spp", cmd.spp, "Samples per pixel of the test renders (default: the scene's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--reference-spp", cmd.reference_spp, "Samples per pixel of the references (with --update)")
      ->check(CLI::PositiveNumber);
  app.add_option("--threads", cmd.threads, "Render threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--scene", cmd.only, "Run only this scene (file name without .json; repeatable)");
  app.add_option("--output-dir", cmd.output_dir, "Where failing scenes' renders and p-value images go")
      ->capture_default_str()
      ->check(ochre::non_empty_path());
  auto* html = app.add_option("--html", cmd.html,
                              "Write a static HTML report into this directory (replaced as a whole; "
                              "only an earlier report or an empty directory is replaced)")
                   ->check(ochre::non_empty_path());
  app.add_option("--history", cmd.history,
                 "Earlier runs for the report's history: JUnit files, report directories or directories of "
                 "JUnit files (oldest first)")
      ->needs(html)
      ->check(ochre::non_empty_path());
  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  ochre::install_signal_cleanup();
  return run(cmd);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-regress", [&] { return regress_command(argc, argv); });
}
