// ochre-vgroove maps and profile (docs/tools.md): the figures of Saint-Pierre et al. 2019 (Figs 6, 8
// and 9). Single maps are written here (OIIO); labelled grids and plots are drawn by
// tools/scripts/plot_vgroove.py from the maps and CSV written here.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>

#include "renderer/output/output_files.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/cli/csv_columns.h"
#include "tools/cli/program.h"
#include "tools/cli/python_script.h"
#include "tools/vgroove/vgroove_commands.h"
#include "tools/vgroove/vgroove_inputs.h"
#include "tools/vgroove/vgroove_maps.h"
#include "tools/vgroove/vgroove_material.h"
#include "tools/vgroove/vgroove_png.h"
#include "tools/vgroove/vgroove_profile.h"
#include "tools/vgroove/vgroove_scratch_dir.h"
#include "tools/vgroove/vgroove_text_table.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

double single_alpha(const std::string& text) {
  const std::vector<double> alphas = parse_number_list("--alpha", text);
  if (alphas.size() != 1) throw InputError(fmt::format("--alpha: give one dihedral angle, not '{}'", text));
  check_alphas("--alpha", alphas);
  return alphas[0];
}

struct Panel {
  const VGrooveMaterial* material;
  double alpha_deg;
  ChainModel model;
};

std::string panel_title(const Panel& p) {
  return fmt::format("{}, alpha {} deg, {} model", p.material->label(), table_number(p.alpha_deg),
                     model_name(p.model));
}

// Refuses outputs that could destroy data (docs/cli.md, "Output files"): ochre-vgroove reads no file, so
// this checks the outputs themselves and that no two are the same file.
void check_outputs(const std::string& first, const std::string& second) {
  std::vector<fs::path> outputs{first};
  if (!second.empty()) outputs.emplace_back(second);
  check_output_files(outputs, InputFileLog{});
}

int write_grid(const MapsArgs& args, const std::vector<Panel>& panels) {
  const ScratchDir scratch{args.output + ".panels"};
  TextTable manifest{{"material", "alpha_deg", "model", "colour_png", "counts_png"}, {}};
  for (size_t i = 0; i < panels.size(); ++i) {
    const Panel& p = panels[i];
    const ReflectanceMaps maps = reflectance_maps(*p.material, p.alpha_deg, p.model, args.size);
    const fs::path colour = scratch.path() / fmt::format("colour_{}.png", i);
    const fs::path counts = scratch.path() / fmt::format("counts_{}.png", i);
    write_map_png(colour, args.size, maps.colour, panel_title(p));
    write_map_png(counts, args.size, maps.counts, panel_title(p) + ": reflection counts");
    manifest.rows.push_back({p.material->label(), table_number(p.alpha_deg), std::string(model_name(p.model)),
                             colour.string(), counts.string()});
  }
  const fs::path manifest_path = scratch.path() / "panels.csv";
  write_text_file(manifest_path, manifest.csv());
  OutputTransaction outputs;
  std::vector<std::string> script_args{"grid", manifest_path.string(),
                                       outputs.add(args.output).temp_path().string()};
  if (!args.counts.empty()) script_args.push_back(outputs.add(args.counts).temp_path().string());
  const fs::path script = tool_script("plot_vgroove.py");
  if (!run_python(script, script_args)) {
    std::cerr << fmt::format(
        "ochre-vgroove: internal error: {} not written ({} failed; is matplotlib installed?)\n", args.output,
        script.string());
    return kExitInternalError;
  }
  outputs.commit();
  return 0;
}

}  // namespace

int run_maps(const MapsArgs& args) {
  const std::vector<VGrooveMaterial> materials =
      VGrooveMaterial::parse_list(args.material.name, args.material.ior);
  const std::vector<double> alphas = parse_number_list("--alpha", args.alphas);
  check_alphas("--alpha", alphas);
  const std::vector<ChainModel> models = parse_models("--model", args.models);
  if (args.size < 3 || args.size > 4096)
    throw InputError(fmt::format("--size: {} pixels is outside [3, 4096]", args.size));
  if (args.output.empty()) throw InputError("-o/--output: give the PNG file to write");
  check_outputs(args.output, args.counts);

  std::vector<Panel> panels;
  for (const VGrooveMaterial& m : materials)
    for (ChainModel model : models)
      for (double alpha : alphas) panels.push_back({&m, alpha, model});
  if (args.grid || panels.size() > 1) return write_grid(args, panels);

  const ReflectanceMaps maps = reflectance_maps(*panels[0].material, alphas[0], models[0], args.size);
  OutputTransaction outputs;
  write_map_png(outputs.add(args.output), args.size, maps.colour, panel_title(panels[0]));
  if (!args.counts.empty())
    write_map_png(outputs.add(args.counts), args.size, maps.counts,
                  panel_title(panels[0]) + ": reflection counts");
  outputs.commit();
  return 0;
}

int run_profile(const ProfileArgs& args) {
  const VGrooveMaterial material = VGrooveMaterial::parse(args.material.name, args.material.ior);
  const double alpha = single_alpha(args.alpha);
  const std::vector<ChainModel> models = parse_models("--model", args.models);
  if (!(args.step > 0.0 && args.step <= 10.0))
    throw InputError(fmt::format("--step: {} degrees is outside (0, 10]", args.step));
  if (args.output.empty()) throw InputError("-o/--output: give the CSV file to write");
  check_outputs(args.output, args.png);

  TextTable csv{{"phi_deg", "theta_deg", "model", "L"}, {}};
  for (const ProfilePoint& p : lightness_profiles(material, alpha, models, args.step))
    csv.rows.push_back({table_number(p.phi_deg), table_number(p.theta_deg), std::string(model_name(p.model)),
                        fmt::format("{:.4f}", p.lightness)});
  // The CSV and the plot are written together: when the plot fails, neither is.
  OutputTransaction outputs;
  const AtomicOutput& csv_output = outputs.add(args.output);
  write_text_file(csv_output, csv.csv());
  if (!args.png.empty()) {
    const fs::path script = tool_script("plot_vgroove.py");
    const std::string title = fmt::format("{}, alpha = {} deg", material.label(), table_number(alpha));
    if (!run_python(script, {"profile", csv_output.temp_path().string(),
                             outputs.add(args.png).temp_path().string(), title})) {
      std::cerr << fmt::format(
          "ochre-vgroove: internal error: {} and {} not written ({} failed; is matplotlib installed?)\n",
          args.output, args.png, script.string());
      return kExitInternalError;
    }
  }
  outputs.commit();
  return 0;
}

}  // namespace ochre
