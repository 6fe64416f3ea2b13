// ochre-brdf: the material explorer (docs/tools.md). Works for any material of the scene format.
//   ochre-brdf eval   --material MAT.json --input pairs.csv --output values.csv
//   ochre-brdf albedo --material MAT.json [--lambda 550] [--angles 0,10,...,89] [--samples N] [--output F]
//   ochre-brdf plot   --material MAT.json --output plot.png [--incidence 0,30,60] [--lambda 550] [--csv F]
//   ochre-brdf chi2   --material MAT.json [--incidence 0,30,60,85] [--lambda 550] [--samples N] [--output F]
// Exit codes (docs/cli.md, "Exit codes"): 0 = done, 4 = chi2 rejected the sampler, 2 = bad input or usage,
// 1 = the plot script failed, or an internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "ochre/version.h"
#include "renderer/util/signal_cleanup.h"
#include "tools/brdf/brdf_commands.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"

namespace {

void add_material_options(CLI::App& command, ochre::MaterialArgs& material) {
  command.add_option("--material", material.file, "One material in the scene format (JSON)")->required();
  command.add_option("--name", material.name, "Material to use when the file has a \"materials\" object");
}

int brdf_command(int argc, char** argv) {
  CLI::App app{"ochre-brdf: evaluate, integrate, plot and check the sampling of any material"};
  app.set_version_flag("--version", "ochre-brdf " OCHRE_VERSION);
  app.require_subcommand(1);

  ochre::EvalArgs eval;
  CLI::App* eval_cmd =
      app.add_subcommand("eval", "BRDF values (Mueller M00, 1/sr, no cosine) at given pairs");
  add_material_options(*eval_cmd, eval.material);
  eval_cmd->add_option("--input", eval.input, "CSV with wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,lambda_nm")->required();
  eval_cmd->add_option("--output", eval.output, "CSV: the input columns plus f")->required();

  ochre::AlbedoArgs albedo;
  CLI::App* albedo_cmd = app.add_subcommand("albedo", "Directional albedo: Monte Carlo and quadrature");
  add_material_options(*albedo_cmd, albedo.material);
  albedo_cmd->add_option("--lambda", albedo.lambda_nm, "Wavelength (nm)")->capture_default_str();
  albedo_cmd->add_option("--angles", albedo.angles_deg, "Polar angles of wo (degrees)")->delimiter(',');
  albedo_cmd->add_option("--samples", albedo.samples, "Monte-Carlo samples per angle")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check());
  albedo_cmd->add_option("--seed", albedo.seed, "Seed")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check());
  albedo_cmd->add_option("--output", albedo.output, "CSV file (default: standard output)");

  ochre::PlotArgs plot;
  CLI::App* plot_cmd = app.add_subcommand("plot", "Incidence-plane and polar plots (PNG, needs matplotlib)");
  add_material_options(*plot_cmd, plot.material);
  plot_cmd->add_option("--output", plot.output, "PNG file")->required();
  plot_cmd->add_option("--incidence", plot.incidence_deg, "Incidence angles (degrees)")->delimiter(',');
  plot_cmd->add_option("--lambda", plot.lambda_nm, "Wavelength (nm)")->capture_default_str();
  plot_cmd->add_option("--csv", plot.csv, "Also keep the plotted values in this CSV")
      ->check(ochre::non_empty_path());

  ochre::Chi2Args chi2;
  CLI::App* chi2_cmd = app.add_subcommand("chi2", "Chi-square test of sample() against pdf()");
  add_material_options(*chi2_cmd, chi2.material);
  chi2_cmd->add_option("--incidence", chi2.incidence_deg, "Polar angles of wo (degrees)")->delimiter(',');
  chi2_cmd->add_option("--lambda", chi2.lambda_nm, "Wavelength (nm)")->capture_default_str();
  chi2_cmd->add_option("--samples", chi2.samples, "Samples per angle")->capture_default_str();
  chi2_cmd->add_option("--alpha", chi2.alpha, "Overall significance level")->capture_default_str();
  chi2_cmd->add_option("--seed", chi2.seed, "Seed")->capture_default_str()->check(ochre::unsigned_64_check());
  chi2_cmd->add_option("--output", chi2.output, "CSV file (default: standard output)");

  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  ochre::install_signal_cleanup();
  if (*eval_cmd) return ochre::run_eval(eval);
  if (*albedo_cmd) return ochre::run_albedo(albedo);
  if (*plot_cmd) return ochre::run_plot(plot);
  return ochre::run_chi2(chi2);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-brdf", [&] { return brdf_command(argc, argv); });
}
