// ochre-diff: compares a linear EXR with a reference EXR (docs/tools.md).
//   ochre-diff TEST.exr REFERENCE.exr [--json] [--heatmap OUT.png] [--max-rmse X] ...
// Exit codes (docs/cli.md, "Exit codes"): 0 = within every threshold, 4 = a threshold exceeded, 2 = bad input
// or usage, 1 = internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "ochre/version.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/image/exr_reader.h"
#include "renderer/output/output_files.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/signal_cleanup.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"

namespace {

const char* const kChannelNames[3] = {"R", "G", "B"};

// The default display transform for CIEDE2000: clamp + sRGB transfer, as `ochre render --png` with
// --ocio-config none, so that results do not depend on $OCIO.
ochre::DisplayOptions no_ocio() {
  ochre::DisplayOptions options;
  options.ocio_config = "none";
  return options;
}

struct DiffCommand {
  std::string test, reference;
  bool json = false;
  std::string heatmap, heatmap_metric = "de00";
  std::optional<double> heatmap_scale;
  ochre::DisplayOptions display = no_ocio();
  ochre::MetricThresholds thresholds;
};

void print_table(const DiffCommand& cmd, const ochre::RgbImage& image, const ochre::ImageMetrics& m) {
  fmt::print("ochre-diff: {} vs reference {} ({}x{}, {}, R G B channels)\n", cmd.test, cmd.reference,
             image.width, image.height, image.working_space);
  const auto row = [](const char* name, double value, const std::string& note = "") {
    if (note.empty())
      fmt::print("  {:<11} {:.6g}\n", name, value);
    else
      fmt::print("  {:<11} {:<12.6g}{}\n", name, value, note);
  };
  row("rmse", m.rmse);
  row("relmse", m.relmse, fmt::format("(epsilon {:g})", ochre::kRelMseEpsilon));
  row("max-error", m.max_error,
      fmt::format("at x={} y={} channel {}", m.max_error_x, m.max_error_y,
                  kChannelNames[m.max_error_channel]));
  row("mean-de00", m.mean_de00);
  row("max-de00", m.max_de00);
}

nlohmann::json metrics_json(const DiffCommand& cmd, const ochre::RgbImage& image,
                            const ochre::ImageMetrics& m, const std::vector<std::string>& exceeded) {
  nlohmann::json j;
  j["test"] = cmd.test;
  j["reference"] = cmd.reference;
  j["width"] = image.width;
  j["height"] = image.height;
  j["working_space"] = image.working_space;
  j["rmse"] = m.rmse;
  j["relmse"] = m.relmse;
  j["relmse_epsilon"] = ochre::kRelMseEpsilon;
  j["max_error"] = m.max_error;
  j["max_error_at"] = {
      {"x", m.max_error_x}, {"y", m.max_error_y}, {"channel", kChannelNames[m.max_error_channel]}};
  j["mean_de00"] = m.mean_de00;
  j["max_de00"] = m.max_de00;
  j["exceeded"] = exceeded;
  j["pass"] = exceeded.empty();
  return j;
}

// Writes the heat-map and returns the line describing its scale.
std::string write_heatmap(const DiffCommand& cmd, const ochre::RgbImage& image,
                          const ochre::ImageComparison& diff) {
  const bool use_de = cmd.heatmap_metric == "de00";
  const std::vector<float>& values = use_de ? diff.maps.de00 : diff.maps.abs_luminance;
  double scale = 0.0;
  for (float v : values) scale = std::max(scale, static_cast<double>(v));
  if (cmd.heatmap_scale) scale = *cmd.heatmap_scale;
  ochre::write_heatmap_png(cmd.heatmap, image.width, image.height, values, scale);
  return fmt::format("heat-map {}: {} from 0 (white) to {:.6g} (dark red) and above", cmd.heatmap,
                     use_de ? "CIEDE2000" : "luminance of |a-b|", scale);
}

int run_diff(const DiffCommand& cmd) {
  if (!cmd.heatmap.empty()) ochre::check_output_writable(cmd.heatmap);
  ochre::InputFileLog inputs;
  const ochre::InputFileLog::Recording recording(inputs);  // the images and the OCIO config
  const ochre::RgbImage test = ochre::rgb_from_exr(ochre::read_exr(cmd.test), cmd.test);
  const ochre::RgbImage reference = ochre::rgb_from_exr(ochre::read_exr(cmd.reference), cmd.reference);
  ochre::check_comparable(test, reference, cmd.test, cmd.reference);

  const ochre::ImageComparison diff = ochre::compare_images(test, reference, cmd.display);
  if (!cmd.heatmap.empty()) ochre::check_output_files({cmd.heatmap}, inputs);
  const std::vector<std::string> exceeded = ochre::exceeded_thresholds(diff.metrics, cmd.thresholds);
  const std::string heatmap_line = cmd.heatmap.empty() ? "" : write_heatmap(cmd, test, diff);

  if (cmd.json) {
    nlohmann::json j = metrics_json(cmd, test, diff.metrics, exceeded);
    if (!cmd.heatmap.empty()) j["heatmap"] = heatmap_line;
    std::cout << j.dump(2) << "\n";
  } else {
    print_table(cmd, test, diff.metrics);
    if (!heatmap_line.empty()) fmt::print("{}\n", heatmap_line);
  }
  std::fflush(stdout);  // the table first, then the verdict on stderr
  for (const std::string& line : exceeded) fmt::print(stderr, "ochre-diff: threshold exceeded: {}\n", line);
  return exceeded.empty() ? ochre::kExitDone : ochre::kExitCheckFailed;
}

int diff_command(int argc, char** argv) {
  CLI::App app{"ochre-diff: compare a linear EXR with a reference EXR (R, G, B channels)"};
  app.set_version_flag("--version", "ochre-diff " OCHRE_VERSION);
  DiffCommand cmd;
  double rmse = 0, relmse = 0, max_error = 0, max_de = 0, heatmap_scale = 0;
  std::string ocio, display, view;

  app.add_option("test", cmd.test, "Image to check (EXR)")->required();
  app.add_option("reference", cmd.reference, "Reference image (EXR)")->required();
  app.add_flag("--json", cmd.json, "Print the metrics as JSON");
  app.add_option("--heatmap", cmd.heatmap, "Write an error heat-map PNG")->check(ochre::non_empty_path());
  app.add_option("--heatmap-metric", cmd.heatmap_metric, "de00 (default) | luminance")
      ->check(CLI::IsMember({"de00", "luminance"}));
  auto* scale_opt =
      app.add_option("--heatmap-scale", heatmap_scale, "Error shown as full red (default: the max)")
          ->check(ochre::finite_positive());
  auto* rmse_opt = app.add_option("--max-rmse", rmse, "Fail (exit 4) when RMSE exceeds this")
                       ->check(ochre::finite_non_negative());
  auto* relmse_opt = app.add_option("--max-relmse", relmse, "Fail when relative MSE exceeds this")
                         ->check(ochre::finite_non_negative());
  auto* error_opt = app.add_option("--max-error", max_error, "Fail when max |a-b| exceeds this")
                        ->check(ochre::finite_non_negative());
  auto* de_opt = app.add_option("--max-de", max_de, "Fail when mean CIEDE2000 exceeds this")
                     ->check(ochre::finite_non_negative());
  auto* ocio_opt = app.add_option("--ocio-config", ocio,
                                  "Display transform for CIEDE2000: OCIO config path, 'builtin' or 'none' "
                                  "(default: none = clamp + sRGB transfer, as `ochre render --png`)");
  auto* display_opt = app.add_option("--display", display, "OCIO display (default: the config's)");
  auto* view_opt = app.add_option("--view", view, "OCIO view (default: the display's)");

  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  if (*scale_opt) cmd.heatmap_scale = heatmap_scale;
  if (*rmse_opt) cmd.thresholds.rmse = rmse;
  if (*relmse_opt) cmd.thresholds.relmse = relmse;
  if (*error_opt) cmd.thresholds.max_error = max_error;
  if (*de_opt) cmd.thresholds.max_de = max_de;
  if (*ocio_opt) cmd.display.ocio_config = ocio;
  if (*display_opt) cmd.display.display = display;
  if (*view_opt) cmd.display.view = view;

  ochre::install_signal_cleanup();
  return run_diff(cmd);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-diff", [&] { return diff_command(argc, argv); });
}
