#include "tools/fit/fit_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <utility>

#include "tools/fit/powder_fit_model.h"

namespace ochre {

namespace {

double significant(double x, int digits) {
  return std::stod(fmt::format("{:.{}g}", x, digits));
}

// The signed outgoing angle when wo lies in the plane of incidence (negative on the light's side).
std::optional<double> signed_in_plane(const Measurement& m) {
  if (m.theta_o == 0.0) return 0.0;
  const double relative = std::remainder(m.phi_o - m.phi_i, 360.0);
  if (std::abs(relative) < 1e-6) return -m.theta_o;
  if (std::abs(std::abs(relative) - 180.0) < 1e-6) return m.theta_o;
  return std::nullopt;
}

std::string error_text(const PowderFitResult& r, int p) {
  switch (r.status[p]) {
    case ParamStatus::kFixed:
      return "fixed";
    case ParamStatus::kAtBound:
      return "at its bound";
    default:
      break;
  }
  const double e = r.standard_error[p];
  if (!std::isfinite(e)) return "undetermined";
  const double v = r.values[p];
  // A percentage only where it means something (not for a value near 0, such as g).
  return e < std::abs(v) ? fmt::format("+- {:<10.3g} ({:.2g} %)", e, 100.0 * e / std::abs(v))
                         : fmt::format("+- {:.3g}", e);
}

// The correlations of the estimates, as a lower triangle, when more than one parameter has an error.
std::string correlation_table(const PowderFitResult& r) {
  const size_t n = r.correlated_params.size();
  if (n < 2) return "";
  std::string text = "  correlations of the estimates (|r| near 1: the data hardly tell the two apart):\n";
  for (size_t k = 1; k < n; ++k) {
    text += fmt::format("    {:<20}", powder_fit_specs()[r.correlated_params[k]].name);
    for (size_t l = 0; l < k; ++l) text += fmt::format(" {:>6.3f}", r.correlation[k][l]);
    text += "\n";
  }
  text += fmt::format("    {:<20}", "");
  for (size_t l = 0; l + 1 < n; ++l)
    text += fmt::format(" {:>6.6}", powder_fit_specs()[r.correlated_params[l]].name);
  return text + "\n";
}

}  // namespace

std::string fit_summary(const PowderFitResult& r, const PowderFitOptions& options) {
  std::string text = fmt::format("  {:<20} {:>12}  {}\n", "parameter", "value", "standard error");
  for (int p = 0; p < kPowderFitParams; ++p) {
    const FitParamSpec& s = powder_fit_specs()[p];
    text += fmt::format("  {:<20} {:>12.6g}  {:<28} {}\n", s.name, r.values[p], error_text(r, p), s.unit);
  }
  if (!r.other_radii.empty())
    text += fmt::format(
        "  radius {:.6g} um is the smallest of the radii that fit as well (sums of squares within one "
        "variance); "
        "the others: {:.3g} um. The model sees the radius only through the grains' albedo, equal there: "
        "measurements at more wavelengths tell them apart, or --fix radius=VALUE\n",
        r.values[kRadius], fmt::join(r.other_radii, ", "));
  if (!r.determined)
    text += "  the data do not determine every fitted parameter (J^T J is singular): fix some with --fix\n";
  text += correlation_table(r);
  text += fmt::format("  MSE {:.6g} (1/sr)^2, RMSE {:.6g} 1/sr, relative RMSE {:.3g} % over {} points\n",
                      r.mse, r.rmse, 100.0 * r.relative_rmse, r.points);
  if (r.fitted > 0) {
    const std::string starts =
        r.grid_points > 0 ? fmt::format("{} starts of a {}-point coarse grid", r.start_runs, r.grid_points)
                          : std::string("--start");
    text += fmt::format(
        "  {} residuals; {} parameters fitted by SLSQP: {} local runs (from {}, then from {} other radii), "
        "{} "
        "objective evaluations, {} model evaluations in all, {:.3f} s\n",
        options.residuals == ResidualKind::kRelative ? "relative" : "absolute", r.fitted, r.local_runs,
        starts, r.local_runs - r.start_runs, r.objective_evaluations, r.residual_evaluations, r.seconds);
  }
  return text;
}

std::string powder_material_json(const PowderValues& values, const FitPigment& pigment,
                                 const std::filesystem::path& json_file, const std::string& data_file) {
  namespace fs = std::filesystem;
  nlohmann::ordered_json material;
  material["type"] = "powder";
  for (int p = 0; p < kPowderFitParams; ++p) material[powder_fit_specs()[p].name] = significant(values[p], 9);
  if (pigment.file().empty()) {
    material["pigment"] = pigment.name();
  } else {
    std::error_code error;
    const fs::path folder = fs::absolute(json_file).parent_path();
    const fs::path relative = fs::relative(fs::absolute(pigment.file()), folder, error);
    material["pigment_file"] = (error || relative.empty() ? fs::absolute(pigment.file()) : relative).string();
  }
  const std::string stem = json_file.stem().string();
  nlohmann::ordered_json j;
  j["description"] = fmt::format(
      "The powder material fitted by ochre-fit to {}: 'materials.{}' (copy it into a scene, or name this "
      "file "
      "with ochre-brdf --material). The rest previews it: a sphere lit from beside the camera, so that its "
      "centre is seen near backscatter (the opposition effect), under a dim sky.",
      fs::path(data_file).filename().string(), kFittedMaterialName);
  j["camera"] = {
      {"type", "perspective"}, {"fov", 30}, {"eye", {0, 0, 5}}, {"target", {0, 0, 0}}, {"up", {0, 1, 0}}};
  j["film"] = {{"resolution", {256, 256}}};
  j["integrator"] = {{"spp", 64}, {"max_depth", 4}};
  j["output"] = {{"exr", stem + "_preview.exr"}, {"png", stem + "_preview.png"}};
  j["materials"] = {{kFittedMaterialName, material}};
  j["lights"] = {{{"type", "point"}, {"position", {0.4, 0.3, 5}}, {"intensity", 120}},
                 {{"type", "environment"}, {"radiance", 0.3}}};
  j["shapes"] = {{{"type", "sphere"}, {"radius", 1}, {"material", kFittedMaterialName}}};
  return j.dump(2) + "\n";
}

std::string fit_table_csv(const std::vector<Measurement>& data, const std::vector<double>& fit,
                          const std::vector<bool>& used) {
  std::string csv = "theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf,fit,residual,used\n";
  for (size_t i = 0; i < data.size(); ++i)
    csv += fmt::format("{},{:.9g},{:.9g},{}\n", measurement_fields(data[i]), fit[i], data[i].brdf - fit[i],
                       used[i] ? 1 : 0);
  return csv;
}

std::string incidence_plane_csv(const std::vector<Measurement>& data, const PowderValues& values,
                                const FitPigment& pigment) {
  std::string csv = "theta_i,lambda_nm,theta_o_signed,kind,brdf\n";
  std::set<std::pair<double, double>> curves;  // (theta_i, lambda)
  for (const Measurement& m : data)
    if (const std::optional<double> angle = signed_in_plane(m)) {
      csv += fmt::format("{:.9g},{:.9g},{:.9g},data,{:.9g}\n", m.theta_i, m.lambda_nm, *angle, m.brdf);
      curves.insert({m.theta_i, m.lambda_nm});
    }
  for (const auto& [theta_i, lambda] : curves) {
    std::vector<Measurement> line;
    for (int half_degrees = -178; half_degrees <= 178; ++half_degrees) {
      Measurement m;
      m.theta_i = theta_i;
      m.lambda_nm = lambda;
      m.theta_o = std::abs(half_degrees) * 0.5;
      m.phi_o = half_degrees < 0 ? 0.0 : 180.0;
      m.wi = direction_from_angles(m.theta_i, 0.0);
      m.wo = direction_from_angles(m.theta_o, m.phi_o);
      line.push_back(m);
    }
    const std::vector<double> brdf = powder_brdf_values(values, line, pigment);
    for (size_t i = 0; i < line.size(); ++i)
      csv +=
          fmt::format("{:.9g},{:.9g},{:.9g},model,{:.9g}\n", theta_i, lambda, (int(i) - 178) * 0.5, brdf[i]);
  }
  return csv;
}

}  // namespace ochre
