// ochre-fit: fits a material model to measured BRDFs and writes a ready-to-use ochre material
// (docs/tools.md). One model for now, the dry-powder BRDF (docs/materials/powder.md, "Fitting
// measurements"):
//   ochre-fit powder --data MEASUREMENTS.csv [--pigment NAME | --pigment-file NK.csv] [--fix NAME=VALUE ...]
//                    [--start NAME=VALUE ...] [--bounds NAME=LOWER:UPPER ...] [--max-theta-i DEG]
//                    [--residuals relative|absolute] [-o MATERIAL.json] [--plot FIT.png] [--csv FIT.csv] [-q]
//   ochre-fit powder --synthesize OUT.csv [--params NAME=VALUE ...] [--noise 0.01] [--seed 1]
//                    [--lambda 450,550,650 | --geometry MEASUREMENTS.csv]
// Exit codes (docs/cli.md, "Exit codes"): 0 = done, 2 = bad input or usage, 1 = the plot script failed
// (nothing written), or an internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "ochre/version.h"
#include "spectra/input_error.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"
#include "tools/fit/fit_commands.h"

namespace {

int fit_command(int argc, char** argv) {
  CLI::App app{"ochre-fit: fit a material model to BRDF measurements and write an ochre material"};
  app.set_version_flag("--version", "ochre-fit " OCHRE_VERSION);
  app.require_subcommand(1);

  ochre::PowderFitArgs fit;
  ochre::PowderSynthesizeArgs synth;
  CLI::App* powder =
      app.add_subcommand("powder", "The dry-powder BRDF (Gerardin, Martinetto and Holzschuch 2023)");
  CLI::Option* data =
      powder->add_option("--data", fit.data, "Measurements: CSV theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf")
          ->check(ochre::non_empty_path());
  CLI::Option* synthesize = powder->add_option(
      "--synthesize", synth.output, "Write synthetic measurements of known parameters to this CSV");
  data->excludes(synthesize);
  CLI::Option* pigment = powder->add_option("--pigment", fit.pigment.name, "Built-in pigment of the grains")
                             ->capture_default_str();
  powder
      ->add_option("--pigment-file", fit.pigment.file, "CSV of the grains' optical constants (columns n, k)")
      ->excludes(pigment);
  powder
      ->add_option("--fix", fit.fix,
                   "Hold a parameter at a value: NAME=VALUE (repeatable, or comma-separated)")
      ->delimiter(',')
      ->needs(data);
  powder
      ->add_option("--start", fit.start,
                   "Start the fit here instead of the coarse grid: NAME=VALUE (others: defaults)")
      ->delimiter(',')
      ->needs(data);
  powder
      ->add_option("--bounds", fit.bounds,
                   "Bounds of a fitted parameter: NAME=LOWER:UPPER (default: docs/tools.md)")
      ->delimiter(',')
      ->needs(data);
  powder
      ->add_option("--max-theta-i", fit.max_theta_i, "Leave out measurements with a larger theta_i (degrees)")
      ->capture_default_str()
      ->needs(data);
  powder
      ->add_option("--residuals", fit.residuals,
                   "relative ((fit - brdf) / brdf) or absolute (fit - brdf, the paper's)")
      ->capture_default_str()
      ->needs(data);
  powder->add_option("-o,--output", fit.material, "Write the fitted material (JSON scene with a preview)")
      ->needs(data)
      ->check(ochre::non_empty_path());
  powder->add_option("--plot", fit.plot, "Plot of data and fit in the plane of incidence (PNG)")
      ->needs(data)
      ->check(ochre::non_empty_path());
  powder->add_option("--csv", fit.csv, "Data, fit and residual per measurement (CSV)")
      ->needs(data)
      ->check(ochre::non_empty_path());
  powder->add_flag("-q,--quiet", fit.quiet, "No progress lines on stderr while fitting")->needs(data);
  powder
      ->add_option("--params", synth.params,
                   "Parameters of the synthetic data: NAME=VALUE (default: the node's)")
      ->delimiter(',')
      ->needs(synthesize);
  powder
      ->add_option("--noise", synth.noise, "Relative standard deviation of the multiplicative Gaussian noise")
      ->capture_default_str()
      ->needs(synthesize);
  powder->add_option("--seed", synth.seed, "Seed of the noise")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check())
      ->needs(synthesize);
  CLI::Option* lambda =
      powder->add_option("--lambda", synth.lambdas_nm, "Wavelengths of the synthetic data (nm)")
          ->delimiter(',')
          ->needs(synthesize);
  powder
      ->add_option("--geometry", synth.geometry,
                   "Synthesize at the geometries and wavelengths of this measurements CSV")
      ->excludes(lambda)
      ->needs(synthesize)
      ->check(ochre::non_empty_path());

  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  if (fit.data.empty() == synth.output.empty())
    throw ochre::InputError("powder: give --data MEASUREMENTS.csv (fit) or --synthesize OUT.csv");
  if (!synth.output.empty()) {
    synth.pigment = fit.pigment;
    return ochre::run_powder_synthesize(synth);
  }
  return ochre::run_powder_fit(fit);
}

}  // namespace

int main(int argc, char** argv) {
  // Bad input (InputError: the file and line, or the option, at fault; ImageError: an output that could not
  // be written, nothing was) exits with 2, anything else with 1 (tools/cli/program.h).
  return ochre::run_program("ochre-fit", [&] { return fit_command(argc, argv); });
}
