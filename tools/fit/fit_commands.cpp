#include "tools/fit/fit_commands.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "renderer/input_error.h"
#include "spectra/sampled_wavelengths.h"
#include "tools/fit/fit_output_set.h"
#include "tools/fit/fit_report.h"
#include "tools/fit/powder_fit.h"
#include "tools/fit/powder_fit_model.h"
#include "tools/fit/synthetic_measurements.h"
#include "tools/python_script.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

FitPigment load_pigment(const PigmentArgs& args) {
  return args.file.empty() ? FitPigment::named(args.name) : FitPigment::from_file(args.file);
}

std::vector<fs::path> inputs_of(const std::string& data, const PigmentArgs& pigment) {
  std::vector<fs::path> inputs;
  if (!data.empty()) inputs.emplace_back(data);
  if (!pigment.file.empty()) inputs.emplace_back(pigment.file);
  return inputs;
}

LocalMethod local_method(const std::string& name) {
  if (name == "slsqp") return LocalMethod::kSlsqp;
  if (name == "bobyqa") return LocalMethod::kBobyqa;
  if (name == "subplex") return LocalMethod::kSubplex;
  throw InputError(fmt::format("--method: '{}' is not slsqp, bobyqa or subplex", name));
}

ResidualKind residual_kind(const std::string& name) {
  if (name == "absolute") return ResidualKind::kAbsolute;
  if (name == "relative") return ResidualKind::kRelative;
  throw InputError(fmt::format("--residuals: '{}' is not absolute or relative", name));
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

}  // namespace

int run_powder_fit(const PowderFitArgs& args) {
  PowderFitOptions options;
  options.residuals = residual_kind(args.residuals);
  options.method = local_method(args.method);
  options.fixed = parse_param_values(args.fix, "--fix");
  if (!(args.max_theta_i >= 0.0 && args.max_theta_i <= 90.0))
    throw InputError(fmt::format("--max-theta-i: {} is outside [0, 90] degrees", args.max_theta_i));
  const FitPigment pigment = load_pigment(args.pigment);
  const std::vector<Measurement> data = read_measurements(args.data);
  const std::vector<bool> used = select_measurements(data, args, pigment, options.residuals);
  std::vector<Measurement> fitted;
  for (size_t i = 0; i < data.size(); ++i)
    if (used[i]) fitted.push_back(data[i]);
  std::vector<fs::path> outputs;
  for (const std::string& output : {args.material, args.plot, args.csv})
    if (!output.empty()) outputs.emplace_back(output);
  check_fit_outputs(outputs, inputs_of(args.data, args.pigment));

  std::cout << fmt::format("ochre-fit powder: {}: {} measurements fitted ({} left out by --max-theta-i {}), {}\n",
                           args.data, fitted.size(), data.size() - fitted.size(), args.max_theta_i,
                           pigment.description());
  if (fitted.empty()) throw InputError(fmt::format("{}: no measurement has theta_i <= {}", args.data, args.max_theta_i));
  const PowderFitResult result = fit_powder(fitted, pigment, options);
  std::cout << fit_summary(result, options);

  FitOutputSet files;
  if (!args.material.empty())
    files.add_text(args.material, powder_material_json(result.values, pigment, args.material));
  if (!args.csv.empty())
    files.add_text(args.csv, fit_table_csv(data, powder_brdf_values(result.values, data, pigment), used));
  if (!args.plot.empty()) {
    const AtomicOutput& png = files.add(args.plot);
    const AtomicOutput values(args.plot + ".values.csv");  // never committed: removed when done
    write_temporary_text(values.temp_path(), incidence_plane_csv(fitted, result.values, pigment), args.plot);
    const fs::path script = tool_script("plot_fit.py");
    const std::string title = fmt::format("{} ({})", fs::path(args.data).filename().string(), pigment.description());
    if (!run_python(script, {values.temp_path().string(), png.temp_path().string(), title})) {
      std::cerr << fmt::format("ochre-fit: error: plot {} not written ({} failed; is matplotlib installed?); "
                               "no output written\n",
                               args.plot, script.string());
      return 1;
    }
  }
  files.commit();
  for (const std::string& output : {args.material, args.plot, args.csv})
    if (!output.empty()) std::cout << "wrote " << output << "\n";
  return 0;
}

int run_powder_synthesize(const PowderSynthesizeArgs& args) {
  const std::array<std::optional<double>, kPowderFitParams> given = parse_param_values(args.params, "--params");
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
  const FitPigment pigment = load_pigment(args.pigment);
  for (double lambda : args.lambdas_nm) pigment.check_index(lambda);
  check_fit_outputs({args.output}, inputs_of("", args.pigment));

  std::vector<Measurement> grid = goniophotometer_grid(args.lambdas_nm);
  synthesize_brdf(grid, values, pigment, args.noise, args.seed);
  std::string csv = fmt::format("# synthetic measurements of the powder BRDF (ochre-fit powder --synthesize), {}\n#",
                                pigment.description());
  for (int p = 0; p < kPowderFitParams; ++p) csv += fmt::format(" {}={:.9g}", powder_fit_specs()[p].name, values[p]);
  csv += fmt::format("\n# multiplicative Gaussian noise {:.9g}, seed {}\n", args.noise, args.seed);
  csv += fmt::format("{}\n", fmt::join(kMeasurementColumns, ","));
  for (const Measurement& m : grid) csv += measurement_fields(m) + "\n";
  FitOutputSet files;
  files.add_text(args.output, csv);
  files.commit();
  std::cout << fmt::format("wrote {} measurements to {}\n", grid.size(), args.output);
  return 0;
}

}  // namespace ochre
