#include "tools/fit/fit_commands.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "renderer/output/output_files.h"
#include "renderer/util/output_transaction.h"
#include "renderer/util/progress.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "spectra/sampled_wavelengths.h"
#include "tools/cli/program.h"
#include "tools/cli/python_script.h"
#include "tools/fit/fit_report.h"
#include "tools/fit/powder_fit.h"
#include "tools/fit/powder_fit_model.h"
#include "tools/fit/synthetic_measurements.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

FitPigment load_pigment(const PigmentArgs& args) {
  return args.file.empty() ? FitPigment::named(args.name) : FitPigment::from_file(args.file);
}

ResidualKind residual_kind(const std::string& name) {
  if (name == "absolute") return ResidualKind::kAbsolute;
  if (name == "relative") return ResidualKind::kRelative;
  throw InputError(fmt::format("--residuals: '{}' is not absolute or relative", name));
}

// --fix, --start and --bounds, each checked alone and against the others: a held parameter has no start
// or bounds, a start lies within its parameter's bounds.
void parse_parameter_options(const PowderFitArgs& args, PowderFitOptions& options) {
  options.fixed = parse_param_values(args.fix, "--fix");
  options.start = parse_param_values(args.start, "--start");
  const std::array<std::optional<ParamBounds>, kPowderFitParams> bounds =
      parse_param_bounds(args.bounds, "--bounds");
  for (int p = 0; p < kPowderFitParams; ++p) {
    const char* name = powder_fit_specs()[p].name;
    if (bounds[p]) options.bounds[p] = *bounds[p];
    if (options.fixed[p] && (options.start[p] || bounds[p]))
      throw InputError(fmt::format("{}: {} is held by --fix {}={}", options.start[p] ? "--start" : "--bounds",
                                   name, name, *options.fixed[p]));
    if (options.start[p] &&
        !(*options.start[p] >= options.bounds[p].lower && *options.start[p] <= options.bounds[p].upper))
      throw InputError(
          fmt::format("--start {}={}: outside the bounds [{}, {}] of {} (--bounds {}=LOWER:UPPER "
                      "moves them)",
                      name, *options.start[p], options.bounds[p].lower, options.bounds[p].upper, name, name));
  }
}

// The measurements the fit uses: theta_i <= max_theta_i, each checked against the pigment and the kind of
// residuals.
std::vector<bool> select_measurements(const std::vector<Measurement>& data, const PowderFitArgs& args,
                                      const FitPigment& pigment, ResidualKind residuals) {
  std::vector<bool> used;
  for (const Measurement& m : data) {
    used.push_back(m.theta_i <= args.max_theta_i);
    pigment.check_index(m.lambda_nm);
    if (used.back() && residuals == ResidualKind::kRelative && !(m.brdf > 0.0))
      throw InputError(fmt::format("{}: line {}: column brdf: {} is not > 0, as --residuals relative needs",
                                   args.data, m.line, m.brdf));
  }
  return used;
}

// Progress lines go to stderr unless -q or OCHRE_PROGRESS=none.
std::ostream* progress_stream(bool quiet) {
  if (quiet) return nullptr;
  try {
    return resolve_progress_style(false, std::getenv("OCHRE_PROGRESS")) == ProgressStyle::none ? nullptr
                                                                                               : &std::cerr;
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

// Writes the plot through plot_fit.py into the transaction; false when the script failed.
bool add_plot(OutputTransaction& files, const PowderFitArgs& args, const std::vector<Measurement>& fitted,
              const PowderValues& values, const FitPigment& pigment) {
  const AtomicOutput& png = files.add(args.plot);
  const AtomicOutput table(args.plot + ".values.csv");  // never committed: removed when done
  write_text_file(table, incidence_plane_csv(fitted, values, pigment));
  const fs::path script = tool_script("plot_fit.py");
  const std::string title =
      fmt::format("{} ({})", fs::path(args.data).filename().string(), pigment.description());
  if (run_python(script, {table.temp_path().string(), png.temp_path().string(), title})) return true;
  std::cerr << fmt::format(
      "ochre-fit: internal error: plot {} not written ({} failed; is matplotlib installed?); no output "
      "written\n",
      args.plot, script.string());
  return false;
}

}  // namespace

int run_powder_fit(const PowderFitArgs& args) {
  PowderFitOptions options;
  options.residuals = residual_kind(args.residuals);
  parse_parameter_options(args, options);
  if (!(args.max_theta_i >= 0.0 && args.max_theta_i <= 90.0))
    throw InputError(fmt::format("--max-theta-i: {} is outside [0, 90] degrees", args.max_theta_i));
  options.progress = progress_stream(args.quiet);

  InputFileLog inputs;
  const InputFileLog::Recording recording(inputs);  // the measurements and the pigment file
  const FitPigment pigment = load_pigment(args.pigment);
  const std::vector<Measurement> data = read_measurements(args.data);
  const std::vector<bool> used = select_measurements(data, args, pigment, options.residuals);
  std::vector<Measurement> fitted;
  for (size_t i = 0; i < data.size(); ++i)
    if (used[i]) fitted.push_back(data[i]);
  size_t free = 0;
  for (const std::optional<double>& fixed : options.fixed) free += fixed ? 0 : 1;
  if (fitted.size() <= free)
    throw InputError(fmt::format(
        "{}: {} measurement(s){} for {} free parameter(s): need more measurements than "
        "free parameters (or --fix some)",
        args.data, fitted.size(),
        fitted.size() < data.size() ? fmt::format(" with theta_i <= {}", args.max_theta_i) : std::string(),
        free));
  std::vector<fs::path> outputs;
  for (const std::string& output : {args.material, args.plot, args.csv})
    if (!output.empty()) outputs.emplace_back(output);
  check_output_files(outputs, inputs);

  std::cout << fmt::format(
      "ochre-fit powder: {}: {} measurements fitted ({} left out by --max-theta-i {}), {}\n", args.data,
      fitted.size(), data.size() - fitted.size(), args.max_theta_i, pigment.description());
  const PowderFitResult result = fit_powder(fitted, pigment, options);
  std::cout << fit_summary(result, options);

  OutputTransaction files;
  if (!args.material.empty())
    write_text_file(files.add(args.material),
                    powder_material_json(result.values, pigment, args.material, args.data));
  if (!args.csv.empty())
    write_text_file(files.add(args.csv),
                    fit_table_csv(data, powder_brdf_values(result.values, data, pigment), used));
  if (!args.plot.empty() && !add_plot(files, args, fitted, result.values, pigment)) return kExitInternalError;
  files.commit();
  for (const std::string& output : {args.material, args.plot, args.csv})
    if (!output.empty()) std::cout << "wrote " << output << "\n";
  return 0;
}

int run_powder_synthesize(const PowderSynthesizeArgs& args) {
  const std::array<std::optional<double>, kPowderFitParams> given =
      parse_param_values(args.params, "--params");
  PowderValues values = powder_default_values();
  for (int p = 0; p < kPowderFitParams; ++p)
    if (given[p]) values[p] = *given[p];
  if (!(args.noise >= 0.0 && args.noise < 1.0))
    throw InputError(fmt::format("--noise: {} is outside [0, 1)", args.noise));
  if (args.lambdas_nm.empty()) throw InputError("--lambda: give at least one wavelength");
  for (double lambda : args.lambdas_nm)
    if (!(lambda >= kLambdaMin && lambda <= kLambdaMax))
      throw InputError(fmt::format("--lambda: {} nm is outside ochre's spectral range [{}, {}] nm", lambda,
                                   kLambdaMin, kLambdaMax));
  InputFileLog inputs;
  const InputFileLog::Recording recording(inputs);  // the pigment file and the geometry
  const FitPigment pigment = load_pigment(args.pigment);
  std::vector<Measurement> grid =
      args.geometry.empty() ? goniophotometer_grid(args.lambdas_nm) : read_measurements(args.geometry);
  for (const Measurement& m : grid) pigment.check_index(m.lambda_nm);
  check_output_files({args.output}, inputs);

  synthesize_brdf(grid, values, pigment, args.noise, args.seed);
  std::string csv =
      fmt::format("# synthetic measurements of the powder BRDF (ochre-fit powder --synthesize), {}\n#",
                  pigment.description());
  for (int p = 0; p < kPowderFitParams; ++p)
    csv += fmt::format(" {}={:.9g}", powder_fit_specs()[p].name, values[p]);
  csv += fmt::format("\n# multiplicative Gaussian noise {:.9g}, seed {}\n", args.noise, args.seed);
  csv += fmt::format("{}\n", fmt::join(kMeasurementColumns, ","));
  for (const Measurement& m : grid) csv += measurement_fields(m) + "\n";
  OutputTransaction files;
  write_text_file(files.add(args.output), csv);
  files.commit();
  std::cout << fmt::format("wrote {} measurements to {}\n", grid.size(), args.output);
  return 0;
}

}  // namespace ochre
