#pragma once
// The start points of ochre-fit's local runs (powder_fit.h, step 1): a grid over the bounds of the four
// nonlinear parameters (g, kappa, radius, correlation_length) with the two amplitudes, in which the BRDF
// is linear, solved exactly at every grid point (bounded linear least squares), and the grid's local
// minima as starts.

#include <array>
#include <vector>

#include "tools/fit/fit_pigment.h"
#include "tools/fit/measurements.h"
#include "tools/fit/powder_fit_params.h"

namespace ochre {

struct GridStart {
  double sum_of_squares = 0;  // of weight (fit - brdf)
  PowderValues values{};
};

struct GridProblem {
  const std::vector<Measurement>& data;
  const std::vector<double>& weights;  // residual = weight (fit - brdf)
  const FitPigment& pigment;
  const PowderBounds& bounds;
  PowderValues held{};                        // the values of the parameters that are not fitted
  std::array<bool, kPowderFitParams> free{};  // fitted parameters
};

// `count` values at the centres of equal cells over the bounds, in the fitted coordinate (log-spaced for
// the logarithmic parameters): g over [-0.95, 0.95] in 5 gives -0.76, -0.38, 0, 0.38, 0.76.
std::vector<double> grid_axis(int param, const ParamBounds& bounds, int count);

// v with the free amplitudes replaced by their best values for v's nonlinear parameters, and its sum of
// squares.
GridStart with_best_amplitudes(const GridProblem& problem, PowderValues v);

// At most `count` starts, best first: the grid points no worse than any of their neighbours (the sum of
// squares has several basins: the radius acts through the grains' albedo alone, which Mie resonances make
// non-monotonic in it; the width of the backscattering peak trades kappa against the albedo). `grid_points`
// receives the number of points of the grid.
std::vector<GridStart> powder_grid_starts(const GridProblem& problem, int count, int& grid_points);

}  // namespace ochre
