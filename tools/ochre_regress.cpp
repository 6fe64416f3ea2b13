// ochre-regress: noise-aware image regression suite (docs/tools.md).
//   ochre-regress DIR [--update] [--junit OUT.xml] [--spp N] [--reference-spp N] [--threads N]
// Renders every DIR/*.json scene and compares its luminance with DIR/references/<name>.exr by a per-pixel
// z-test with Sidak correction (renderer/regression_compare.h).
// Exit codes: 0 = every scene passes, 1 = a scene fails, 2 = bad input or usage.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "ochre/version.h"
#include "renderer/atomic_file.h"
#include "renderer/exr_reader.h"
#include "renderer/input_error.h"
#include "renderer/output_files.h"
#include "renderer/output_transaction.h"
#include "renderer/regression_compare.h"
#include "renderer/render.h"
#include "renderer/render_output.h"
#include "renderer/scene_loader.h"
#include "renderer/signal_cleanup.h"

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
  uint32_t spp = 0;
};

RenderedScene render_scene(const fs::path& file, uint32_t spp, uint64_t seed, std::optional<int> threads) {
  ochre::SceneOverrides overrides;
  overrides.spp = spp;
  overrides.seed = seed;
  overrides.threads = threads;
  const auto scene = ochre::load_scene(file, overrides);
  RenderedScene r;
  r.film = std::make_unique<ochre::Film>(scene->settings.width, scene->settings.height);
  ochre::render(*scene, *r.film);
  r.outputs = scene->outputs;
  r.spp = spp;
  return r;
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
  return ochre::load_scene(file)->settings;
}

void update_reference(const RegressCommand& cmd, const fs::path& file, const ochre::InputFileLog& inputs) {
  const auto start = std::chrono::steady_clock::now();
  const ochre::RenderSettings settings = scene_settings(file);
  const fs::path out = reference_path(cmd.dir, file.stem().string());
  fs::create_directories(out.parent_path());
  ochre::check_output_files({out}, inputs);  // before the render: the scene and its files are read
  const uint32_t spp = cmd.reference_spp.value_or(kReferenceSppFactor * settings.spp);
  const RenderedScene r = render_scene(file, spp, kReferenceSeedOffset + settings.seed, cmd.threads);
  // write_exr goes through a temporary file and a rename: an interrupted update keeps the old reference.
  ochre::write_exr(out, ochre::make_reference_image(*r.film, ochre::film_to_rgb(*r.film, r.outputs), spp));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("updated {} ({} spp, seed {}, {:.2f} s)\n", out.string(), spp,
             kReferenceSeedOffset + settings.seed, seconds);
}

SceneOutcome run_scene(const RegressCommand& cmd, const fs::path& file, const ochre::InputFileLog& inputs) {
  const auto start = std::chrono::steady_clock::now();
  SceneOutcome outcome;
  outcome.name = file.stem().string();
  const fs::path ref_file = reference_path(cmd.dir, outcome.name);
  if (!fs::exists(ref_file))
    throw ochre::InputError(ref_file.string() + ": reference missing; create it with `ochre-regress " +
                            cmd.dir + " --update`");
  const ochre::LuminanceEstimate reference =
      ochre::luminance_from_reference(ochre::read_exr(ref_file), ref_file);
  const ochre::RenderSettings settings = scene_settings(file);
  const RenderedScene r = render_scene(file, cmd.spp.value_or(settings.spp), settings.seed, cmd.threads);
  if (r.film->width() != reference.width || r.film->height() != reference.height)
    throw ochre::InputError(fmt::format(
        "{}: reference is {}x{} but the scene renders {}x{}; regenerate it "
        "with `ochre-regress {} --update`",
        ref_file.string(), reference.width, reference.height, r.film->width(), r.film->height(), cmd.dir));
  const ochre::RegressionResult result =
      ochre::compare_luminance(ochre::luminance_from_film(*r.film), reference);
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
    ochre::write_exr(transaction.add(render_exr),
                     ochre::make_reference_image(*r.film, ochre::film_to_rgb(*r.film, r.outputs), r.spp));
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
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void write_junit(const fs::path& path, const std::vector<SceneOutcome>& outcomes) {
  size_t failures = 0;
  double total = 0.0;
  for (const auto& o : outcomes) {
    failures += o.passed ? 0 : 1;
    total += o.seconds;
  }
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += fmt::format(
      "<testsuite name=\"ochre-regress\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
      outcomes.size(), failures, total);
  for (const auto& o : outcomes) {
    xml += fmt::format("  <testcase classname=\"ochre-regress\" name=\"{}\" time=\"{:.3f}\"",
                       xml_escape(o.name), o.seconds);
    if (o.passed) {
      xml += "/>\n";
    } else {
      xml += fmt::format(">\n    <failure message=\"{}\"/>\n  </testcase>\n", xml_escape(o.message));
    }
  }
  xml += "</testsuite>\n";
  ochre::write_text_file(path, xml);
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
  std::vector<SceneOutcome> outcomes;
  for (const auto& file : files) outcomes.push_back(run_scene(cmd, file, inputs));

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
  if (!cmd.junit.empty()) {
    ochre::check_output_files({cmd.junit}, inputs);
    write_junit(cmd.junit, outcomes);
  }
  return all_passed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "ochre-regress: noise-aware image regression tests (per-pixel luminance z-test, Sidak "
      "correction)"};
  app.set_version_flag("--version", "ochre-regress " OCHRE_VERSION);
  RegressCommand cmd;
  app.add_option("dir", cmd.dir, "Folder of *.json scenes with references/<name>.exr")->required();
  app.add_flag("--update", cmd.update,
               "Render the references (16 x the scene's spp, seed 1000 + scene seed)");
  app.add_option("--junit", cmd.junit, "Write a JUnit XML report");
  app.add_option("--spp", cmd.spp, "Samples per pixel of the test renders (default: the scene's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--reference-spp", cmd.reference_spp, "Samples per pixel of the references (with --update)")
      ->check(CLI::PositiveNumber);
  app.add_option("--threads", cmd.threads, "Render threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--scene", cmd.only, "Run only this scene (file name without .json; repeatable)");
  app.add_option("--output-dir", cmd.output_dir, "Where failing scenes' renders and p-value images go")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  ochre::install_signal_cleanup();
  try {
    return run(cmd);
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "ochre-regress: error: out of memory while running the scenes of {}\n", cmd.dir);
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ochre-regress: {}\n", e.what());
    return 2;
  }
}
