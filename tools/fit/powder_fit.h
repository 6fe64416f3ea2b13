#pragma once
// Fits the dry-powder BRDF to measurements (docs/tools.md, ochre-fit): the six parameters of
// powder_fit_params.h, any of them held fixed, by bounded least squares on the BRDF values as the paper
// does (Gerardin, Martinetto and Holzschuch 2023, Sec 5.4; relative residuals by default, its Eq 30's
// absolute ones as an option):
// 1. the starts: the best local minima of a coarse grid over the bounds of the nonlinear parameters
//    (powder_fit_grid.h), or the user's start point;
// 2. SLSQP (bounded_least_squares.h) from each start over all free parameters;
// 3. other radii that fit as well (the grains' albedo, through which alone the radius acts, is not
//    monotonic in it): a scan of the radius and a local run from each of its minima; of the minima as
//    good as the best, the smallest radius is kept, the others reported;
// 4. standard errors and correlations from the Jacobian of the residuals at the optimum.

#include <array>
#include <iosfwd>
#include <optional>
#include <vector>

#include "tools/fit/bounded_least_squares.h"
#include "tools/fit/fit_pigment.h"
#include "tools/fit/measurements.h"
#include "tools/fit/powder_fit_params.h"

namespace ochre {

// Residuals fit - brdf in 1/sr (the paper's Eq 30), or relative to the measurement, (fit - brdf) / brdf:
// the maximum-likelihood choice for noise proportional to the signal.
enum class ResidualKind { kAbsolute, kRelative };

struct PowderFitOptions {
  std::array<std::optional<double>, kPowderFitParams> fixed;
  // When any is given: one local run from there (the other free parameters start at the node's default,
  // clamped into their bounds) instead of the coarse grid. Within the bounds (the caller checks).
  std::array<std::optional<double>, kPowderFitParams> start;
  PowderBounds bounds = powder_default_bounds();
  ResidualKind residuals = ResidualKind::kRelative;
  int grid_starts = 4;               // local runs from the grid (powder_fit_grid.h)
  std::ostream* progress = nullptr;  // progress lines (nullptr: none)
};

enum class ParamStatus { kFitted, kFixed, kAtBound };

struct PowderFitResult {
  PowderValues values{};
  std::array<ParamStatus, kPowderFitParams> status{};
  std::array<double, kPowderFitParams>
      standard_error{};  // NaN unless fitted inside its bounds and determined
  // Correlations of the estimates of the parameters fitted inside their bounds (in their fitted
  // coordinates, powder_fit_params.h), in the order of correlated_params.
  std::vector<int> correlated_params;
  Matrix correlation;
  bool determined = true;  // J^T J invertible over the parameters fitted inside their bounds
  // Other radii that fit as well (within one variance of the sum of squares; see powder_fit.cpp): the
  // model sees the radius only through the grains' albedo, the same at several radii.
  std::vector<double> other_radii;
  double sum_of_squares = 0;   // of the fit's residuals (absolute or relative)
  double mse = 0, rmse = 0;    // of fit - brdf, (1/sr)^2 and 1/sr
  double relative_rmse = 0;    // of (fit - brdf) / brdf over the points with brdf > 0
  int points = 0, fitted = 0;  // measurements, parameters fitted
  int grid_points = 0, start_runs = 0, local_runs = 0, objective_evaluations = 0, residual_evaluations = 0;
  double seconds = 0;
};

// Relative residuals need every brdf > 0 (the caller checks, naming the line). Throws InputError when there
// are not more points than free parameters (the caller checks first, naming the file).
PowderFitResult fit_powder(const std::vector<Measurement>& data, const FitPigment& pigment,
                           const PowderFitOptions& options);

}  // namespace ochre
