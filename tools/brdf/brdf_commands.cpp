#include "tools/brdf/brdf_commands.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "materials/core/pi.h"
#include "materials/lobes/closure_lobe.h"
#include "materials/lobes/directional_albedo.h"
#include "materials/lobes/sampling_check.h"
#include "renderer/output/output_files.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/output_transaction.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"
#include "spectra/sampled_wavelengths.h"
#include "tools/brdf/direction_pairs.h"
#include "tools/brdf/material_probe.h"
#include "tools/cli/csv_columns.h"
#include "tools/cli/program.h"
#include "tools/cli/python_script.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

// Direction at polar angle theta and azimuth phi (degrees) in the local frame.
Vec3 direction_deg(double theta_deg, double phi_deg) {
  const double t = theta_deg * kDegD, p = phi_deg * kDegD;
  return {static_cast<float>(std::sin(t) * std::cos(p)), static_cast<float>(std::sin(t) * std::sin(p)),
          static_cast<float>(std::cos(t))};
}

void check_angles(const std::vector<double>& angles, const char* option) {
  if (angles.empty()) throw InputError(fmt::format("{}: give at least one angle", option));
  for (double a : angles)
    if (!(a >= 0.0 && a < 90.0))
      throw InputError(fmt::format("{}: angle {} is outside [0, 90) degrees", option, a));
}

void check_lambda(float lambda_nm) {
  if (!(lambda_nm >= kLambdaMin && lambda_nm <= kLambdaMax))
    throw InputError(fmt::format("--lambda: {} nm is outside the spectral range [{}, {}] nm", lambda_nm,
                                 kLambdaMin, kLambdaMax));
}

// Writes `text` to `path` atomically, or to standard output when path is empty.
void write_output(const std::string& path, const std::string& text, const InputFileLog& inputs) {
  if (path.empty()) {
    std::cout << text;
    return;
  }
  check_output_files({path}, inputs);
  write_text_file(fs::path(path), text);
}

// The closure's BRDF on a (theta_o, phi_o) grid for each incidence (wi at phi = 0, so phi_o = 0 is the
// light's side: backscatter).
std::string plot_table(MaterialProbe& probe, const PlotArgs& args) {
  const Closure& closure = probe.closure(args.lambda_nm);
  std::string csv = "incidence_deg,theta_o_deg,phi_o_deg,f\n";
  for (double incidence : args.incidence_deg) {
    const Vec3 wi = direction_deg(incidence, 0.0);
    for (int theta = 0; theta <= 89; ++theta)
      for (int phi = 0; phi <= 360; phi += 5) {
        const double f = closure.eval(direction_deg(theta, phi), wi, probe.wavelengths())[0];
        csv += fmt::format("{},{},{},{}\n", table_number(incidence), theta, phi, table_number(f));
      }
  }
  return csv;
}

}  // namespace

int run_eval(const EvalArgs& args) {
  check_output_writable(args.output);
  InputFileLog inputs;
  const InputFileLog::Recording recording(inputs);
  MaterialProbe probe(args.material.file, args.material.name);
  const DirectionPairTable table = read_direction_pairs(args.input);
  std::string csv;
  for (const std::string& column : table.header) csv += column + ",";
  csv += "f\n";
  for (const DirectionPair& row : table.rows) {
    float f = 0.0f;
    try {
      f = probe.closure(row.lambda_nm).eval(row.wo, row.wi, probe.wavelengths())[0];
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: line {}: column lambda_nm: {}", args.input, row.line, e.what()));
    }
    for (const std::string& field : row.fields) csv += field + ",";
    csv += table_number(f) + "\n";
  }
  write_output(args.output, csv, inputs);
  return 0;
}

int run_albedo(const AlbedoArgs& args) {
  check_angles(args.angles_deg, "--angles");
  check_lambda(args.lambda_nm);
  if (args.samples == 0) throw InputError("--samples must be positive");
  InputFileLog inputs;
  const InputFileLog::Recording recording(inputs);
  MaterialProbe probe(args.material.file, args.material.name);
  const Closure& closure = probe.closure(args.lambda_nm);
  std::string csv = "theta_deg,lambda_nm,mc_albedo,mc_se,quadrature_albedo,quadrature_error\n";
  for (double theta : args.angles_deg) {
    const AlbedoEstimate a =
        directional_albedo(closure, direction_deg(theta, 0.0), probe.wavelengths(), args.samples, args.seed);
    csv += fmt::format("{},{},{},{},{},{}\n", table_number(theta), table_number(args.lambda_nm),
                       table_number(a.monte_carlo), table_number(a.monte_carlo_se),
                       table_number(a.quadrature), table_number(a.quadrature_error));
  }
  write_output(args.output, csv, inputs);
  return 0;
}

int run_plot(const PlotArgs& args) {
  check_angles(args.incidence_deg, "--incidence");
  check_lambda(args.lambda_nm);
  if (args.output.empty()) throw InputError("--output: give the PNG file to write");
  InputFileLog inputs;
  const InputFileLog::Recording recording(inputs);
  MaterialProbe probe(args.material.file, args.material.name);
  const std::string csv = plot_table(probe, args);
  std::vector<fs::path> outputs = {args.output};
  if (!args.csv.empty()) outputs.emplace_back(args.csv);
  check_output_files(outputs, inputs);
  // The values go to a temporary CSV, the picture to a temporary PNG; both are renamed (the CSV only
  // when asked for) when the script succeeded, neither otherwise.
  OutputTransaction transaction;
  AtomicOutput& png = transaction.add(args.output);
  AtomicOutput values_only(args.output + ".values.csv");  // never committed: removed when done
  AtomicOutput& values = args.csv.empty() ? values_only : transaction.add(args.csv);
  write_text_file(values, csv);
  const std::string title = fmt::format("{} ({} nm)", probe.name(), table_number(args.lambda_nm));
  const fs::path script = tool_script("plot_brdf.py");
  if (!run_python(script, {values.temp_path().string(), png.temp_path().string(), title})) {
    std::cerr << fmt::format(
        "ochre-brdf: internal error: plot {} not written ({} failed; is matplotlib installed?)\n",
        args.output, script.string());
    return kExitInternalError;
  }
  transaction.commit();
  std::cout << "plot: " << args.output << "\n";
  return 0;
}

int run_chi2(const Chi2Args& args) {
  check_angles(args.incidence_deg, "--incidence");
  check_lambda(args.lambda_nm);
  if (args.samples < 1000) throw InputError("--samples must be at least 1000");
  if (!(args.alpha > 0.0 && args.alpha < 1.0)) throw InputError("--alpha must be in (0, 1)");
  InputFileLog inputs;
  const InputFileLog::Recording recording(inputs);
  MaterialProbe probe(args.material.file, args.material.name);
  const ClosureLobe lobe(probe.closure(args.lambda_nm));
  const double significance = sidak_significance(args.alpha, static_cast<int>(args.incidence_deg.size()));
  std::string csv =
      "theta_o_deg,chi2,dof,p_value,significance,histogrammed,failed,delta,in_empty_cells,weight_mismatches,"
      "pdf_mismatches,pass\n";
  bool all_pass = true;
  for (size_t i = 0; i < args.incidence_deg.size(); ++i) {
    const Chi2Result r = chi2_test(lobe, direction_deg(args.incidence_deg[i], 0.0), probe.wavelengths(), 40,
                                   80, args.samples, args.seed + i);
    const bool pass = r.p_value > significance && r.weight_mismatches == 0 && r.pdf_mismatches == 0 &&
                      r.samples_in_empty_cells == 0;
    all_pass = all_pass && pass;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", table_number(args.incidence_deg[i]),
                       table_number(r.statistic), r.degrees_of_freedom, table_number(r.p_value),
                       table_number(significance), r.samples_histogrammed, r.samples_failed, r.samples_delta,
                       r.samples_in_empty_cells, r.weight_mismatches, r.pdf_mismatches, pass ? "yes" : "no");
  }
  write_output(args.output, csv, inputs);
  std::cerr << fmt::format("ochre-brdf chi2: {}: {}\n", probe.name(), all_pass ? "PASS" : "FAIL");
  return all_pass ? kExitDone : kExitCheckFailed;
}

}  // namespace ochre
