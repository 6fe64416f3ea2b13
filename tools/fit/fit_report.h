#pragma once
// What ochre-fit powder writes (docs/tools.md): the summary it prints, the material JSON, the table of
// data, fit and residuals, and the incidence-plane values that tools/scripts/plot_fit.py draws.

#include <filesystem>
#include <string>
#include <vector>

#include "tools/fit/fit_pigment.h"
#include "tools/fit/measurements.h"
#include "tools/fit/powder_fit.h"

namespace ochre {

// The parameters with their standard errors, the MSE and RMSE, the counts and the time.
std::string fit_summary(const PowderFitResult& result, const PowderFitOptions& options);

// The name of the fitted material in the JSON.
inline constexpr const char* kFittedMaterialName = "powder_fit";

// A scene holding the fitted material as materials.powder_fit ({"type": "powder", ...} with the six
// parameters to 9 significant digits and the pigment) and a preview of it (a sphere lit from beside the
// camera, outputs JSON_STEM_preview.exr/png): `ochre render` renders it as it is, ochre-brdf --material
// reads the material from it. A pigment file is named relative to the JSON's folder, as the scene format
// resolves it.
std::string powder_material_json(const PowderValues& values, const FitPigment& pigment,
                                 const std::filesystem::path& json_file, const std::string& data_file);

// theta_i,phi_i,theta_o,phi_o,lambda_nm,brdf,fit,residual,used: residual = brdf - fit (1/sr), used = 0 for
// the measurements --max-theta-i left out.
std::string fit_table_csv(const std::vector<Measurement>& data, const std::vector<double>& fit,
                          const std::vector<bool>& used);

// theta_i,lambda_nm,theta_o_signed,kind,brdf for the plot: the measurements of the plane of incidence
// (phi_o = phi_i: theta_o negative, on the light's side; phi_o = phi_i + 180: positive) as kind "data", and
// the model every half degree from -89 to 89 for each (theta_i, lambda) of them as kind "model".
std::string incidence_plane_csv(const std::vector<Measurement>& data, const PowderValues& values,
                                const FitPigment& pigment);

}  // namespace ochre
