#include "tools/fit/powder_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <ostream>

#include "spectra/input_error.h"
#include "tools/fit/powder_fit_grid.h"
#include "tools/fit/powder_fit_model.h"

namespace ochre {

namespace {

// The data, the weights and which parameters are fitted: the residuals as a function of the fitted
// coordinates.
struct FitProblem {
  const std::vector<Measurement>& data;
  const FitPigment& pigment;
  const PowderBounds& bounds;
  std::vector<double> weights;  // residual = weight (fit - brdf)
  PowderValues held{};          // the values of the parameters that are not fitted
  std::vector<int> free;        // fitted parameters, in order

  PowderValues values_at(const std::vector<double>& x) const {
    PowderValues v = held;
    for (size_t k = 0; k < free.size(); ++k) v[free[k]] = from_coordinate(free[k], x[k]);
    return v;
  }

  std::vector<double> coordinates_of(const PowderValues& v) const {
    std::vector<double> x;
    for (int p : free) x.push_back(to_coordinate(p, v[p]));
    return x;
  }

  BoundedLeastSquares least_squares() const {
    BoundedLeastSquares ls;
    ls.residuals = [this](const std::vector<double>& x, std::vector<double>& r) {
      const std::vector<double> fit = powder_brdf_values(values_at(x), data, pigment);
      r.resize(fit.size());
      for (size_t i = 0; i < fit.size(); ++i) r[i] = weights[i] * (fit[i] - data[i].brdf);
    };
    for (int p : free) {
      ls.lower.push_back(to_coordinate(p, bounds[p].lower));
      ls.upper.push_back(to_coordinate(p, bounds[p].upper));
    }
    return ls;
  }

  GridProblem grid() const {
    GridProblem g{data, weights, pigment, bounds, held, {}};
    for (int p : free) g.free[p] = true;
    return g;
  }

  // "MSE 1.2e-07" (1/sr)^2, or "relative MSE 1.1e-04" for relative residuals: the mean of the squares.
  std::string mean_square(double sum_of_squares, bool relative) const {
    return fmt::format("{}MSE {:.6g}", relative ? "relative " : "", sum_of_squares / double(data.size()));
  }
};

// The user's start point: the given values, the other free parameters at the node's defaults clamped into
// their bounds.
PowderValues start_point(const FitProblem& problem, const PowderFitOptions& options) {
  PowderValues v = problem.held;
  for (int p : problem.free)
    v[p] = options.start[p]
               ? *options.start[p]
               : std::clamp(powder_fit_specs()[p].fallback, problem.bounds[p].lower, problem.bounds[p].upper);
  return v;
}

// The local runs so far: the best point, the counts and the progress lines.
struct LocalRuns {
  const FitProblem& problem;
  BoundedLeastSquares least_squares;
  PowderFitResult& result;
  std::ostream* progress;
  bool relative;
  std::vector<LocalMinimum> minima;

  // Progress: a line every kProgressEvery evaluations of a run and one at its end.
  static constexpr int kProgressEvery = 10;

  const LocalMinimum& run(const PowderValues& start, const std::string& from) {
    const int number = result.local_runs + 1;
    if (progress)
      least_squares.on_evaluation = [this, number](int evaluation, double sum_of_squares) {
        if (evaluation % kProgressEvery == 0)
          *progress << fmt::format("ochre-fit: run {}, evaluation {}: {}\n", number, evaluation,
                                   problem.mean_square(sum_of_squares, relative))
                    << std::flush;
      };
    minima.push_back(minimise_sum_of_squares(least_squares, problem.coordinates_of(start)));
    const LocalMinimum& m = minima.back();
    ++result.local_runs;
    result.objective_evaluations += m.objective_evaluations;
    result.residual_evaluations += m.residual_evaluations;
    if (progress)
      *progress << fmt::format("ochre-fit: run {} (from {}): {} after {} evaluations ({})\n", number, from,
                               problem.mean_square(m.sum_of_squares, relative), m.objective_evaluations,
                               m.stop)
                << std::flush;
    return m;
  }

  const LocalMinimum& best() const {
    return *std::min_element(minima.begin(), minima.end(), [](const LocalMinimum& a, const LocalMinimum& b) {
      return a.sum_of_squares < b.sum_of_squares;
    });
  }
};

// The minima of the sum of squares over `count` log-spaced radii from `lower` to `upper` (g, kappa and the
// correlation length at `best`, the amplitudes solved exactly at each radius) that could fit as well, but
// for the best fit's own (within 1.5 steps of its radius).
std::vector<GridStart> radius_scan_minima(LocalRuns& runs, const PowderValues& best, double limit,
                                          double lower, double upper, int count) {
  const double lo = std::log(lower), step = (std::log(upper) - lo) / (count - 1);
  const GridProblem grid = runs.problem.grid();
  std::vector<GridStart> scan(count);
  for (int i = 0; i < count; ++i) {
    PowderValues v = best;
    v[kRadius] = std::exp(lo + i * step);
    scan[i] = with_best_amplitudes(grid, v);
    ++runs.result.residual_evaluations;
  }
  std::vector<GridStart> minima;
  for (int i = 0; i < count; ++i) {
    const double sse = scan[i].sum_of_squares;
    const bool minimum = (i == 0 || sse <= scan[i - 1].sum_of_squares) &&
                         (i == count - 1 || sse <= scan[i + 1].sum_of_squares);
    if (minimum && sse <= limit && std::abs(std::log(scan[i].values[kRadius] / best[kRadius])) > 1.5 * step)
      minima.push_back(scan[i]);
  }
  return minima;
}

// The model sees the radius only through the grains' albedo rho(lambda, b), which the Mie resonances of
// weakly absorbing grains make non-monotonic in b (hematite at 700 nm: rho(0.05 um) = rho(0.27 um) =
// rho(0.50 um) = 0.75). At one wavelength several radii then fit equally well; at several, two radii on
// either side of a resonance at one wavelength can fit almost as well, 1 % apart. This finds them: a scan
// over the radius's bounds and a fine one within 5 % of the best, and a local run from each minimum of
// the scans that could come close to the best (re-fitting the other parameters lowers a scan minimum by a
// few variances at most when it is a true alternative).
void add_radius_alternatives(LocalRuns& runs, double variance) {
  const PowderValues best = runs.problem.values_at(runs.best().x);
  const double limit = runs.best().sum_of_squares + 25.0 * variance;
  const ParamBounds& bounds = runs.problem.bounds[kRadius];
  std::vector<GridStart> minima = radius_scan_minima(runs, best, limit, bounds.lower, bounds.upper, 1200);
  const double near_lower = std::max(bounds.lower, best[kRadius] / 1.05);
  const double near_upper = std::min(bounds.upper, best[kRadius] * 1.05);
  for (const GridStart& m : radius_scan_minima(runs, best, limit, near_lower, near_upper, 201))
    if (std::none_of(minima.begin(), minima.end(), [&](const GridStart& other) {
          return std::abs(std::log(other.values[kRadius] / m.values[kRadius])) < 0.002;
        }))
      minima.push_back(m);
  std::sort(minima.begin(), minima.end(),
            [](const GridStart& a, const GridStart& b) { return a.sum_of_squares < b.sum_of_squares; });
  if (minima.size() > 8) minima.resize(8);
  if (runs.progress)
    *runs.progress << fmt::format("ochre-fit: radius scan: {} other minima could fit as well\n",
                                  minima.size())
                   << std::flush;
  for (const GridStart& start : minima)
    runs.run(start.values, fmt::format("radius {:.4g} um", start.values[kRadius]));
}

// True when the fitted coordinate x of `param` lies on one of its bounds.
bool on_bound(const FitProblem& problem, int param, double x) {
  const double lower = to_coordinate(param, problem.bounds[param].lower);
  const double upper = to_coordinate(param, problem.bounds[param].upper);
  const double margin = 1e-6 * (upper - lower);
  return x <= lower + margin || x >= upper - margin;
}

// The fit to keep: among the minima that fit as well as the best, within one variance of its sum of squares
// (statistically indistinguishable), the one with the smallest radius: on the small-grain branch, where rho
// grows monotonically with b, the radius follows from rho alone. The other radii are reported.
std::vector<double> choose_radius(LocalRuns& runs, PowderFitResult& result) {
  const int k = static_cast<int>(std::find(runs.problem.free.begin(), runs.problem.free.end(), kRadius) -
                                 runs.problem.free.begin());
  if (k == static_cast<int>(runs.problem.free.size())) return runs.best().x;
  const double variance =
      runs.best().sum_of_squares / double(runs.problem.data.size() - runs.problem.free.size());
  add_radius_alternatives(runs, variance);
  const double limit = runs.best().sum_of_squares + variance;
  std::vector<const LocalMinimum*> equivalent;
  for (const LocalMinimum& m : runs.minima)
    if (m.sum_of_squares <= limit) equivalent.push_back(&m);
  std::sort(equivalent.begin(), equivalent.end(),
            [k](const LocalMinimum* a, const LocalMinimum* b) { return a->x[k] < b->x[k]; });
  for (const LocalMinimum* m : equivalent) {
    const double radius = from_coordinate(kRadius, m->x[k]);
    const double chosen = from_coordinate(kRadius, equivalent.front()->x[k]);
    const double previous = result.other_radii.empty() ? chosen : result.other_radii.back();
    if (std::abs(std::log(radius / previous)) > 0.01) result.other_radii.push_back(radius);
  }
  return equivalent.front()->x;
}

void summarise_residuals(const std::vector<Measurement>& data, const FitPigment& pigment,
                         PowderFitResult& r) {
  const std::vector<double> fit = powder_brdf_values(r.values, data, pigment);
  double sum = 0, relative = 0;
  int positive = 0;
  for (size_t i = 0; i < data.size(); ++i) {
    const double d = fit[i] - data[i].brdf;
    sum += d * d;
    if (data[i].brdf > 0) relative += (d / data[i].brdf) * (d / data[i].brdf), ++positive;
  }
  r.points = static_cast<int>(data.size());
  r.mse = sum / double(data.size());
  r.rmse = std::sqrt(r.mse);
  r.relative_rmse = positive ? std::sqrt(relative / positive) : 0.0;
}

// Standard errors and correlations of the parameters fitted inside their bounds (those on a bound are held
// there: their error is not that of an interior minimum).
void estimate_errors(FitProblem problem, const std::vector<double>& x, PowderFitResult& r) {
  problem.held = problem.values_at(x);
  std::vector<int> interior;
  for (size_t k = 0; k < problem.free.size(); ++k)
    if (on_bound(problem, problem.free[k], x[k]))
      r.status[problem.free[k]] = ParamStatus::kAtBound;
    else
      interior.push_back(problem.free[k]);
  problem.free = interior;
  if (interior.empty()) return;
  const BoundedLeastSquares ls = problem.least_squares();
  const std::vector<double> xi = problem.coordinates_of(problem.held);
  const std::optional<Matrix> covariance =
      least_squares_covariance(residual_jacobian(ls, xi, &r.residual_evaluations), r.sum_of_squares);
  r.determined = covariance.has_value();
  if (!covariance) return;
  const Matrix& c = *covariance;
  r.correlated_params = interior;
  r.correlation.assign(interior.size(), std::vector<double>(interior.size()));
  for (size_t k = 0; k < interior.size(); ++k) {
    r.standard_error[interior[k]] =
        std::sqrt(c[k][k]) * value_per_coordinate(interior[k], problem.held[interior[k]]);
    for (size_t l = 0; l < interior.size(); ++l) r.correlation[k][l] = c[k][l] / std::sqrt(c[k][k] * c[l][l]);
  }
}

}  // namespace

PowderFitResult fit_powder(const std::vector<Measurement>& data, const FitPigment& pigment,
                           const PowderFitOptions& options) {
  const auto start_time = std::chrono::steady_clock::now();
  FitProblem problem{data, pigment, options.bounds, {}, powder_default_values(), {}};
  PowderFitResult result;
  for (int p = 0; p < kPowderFitParams; ++p) {
    result.standard_error[p] = std::numeric_limits<double>::quiet_NaN();
    if (options.fixed[p]) {
      problem.held[p] = *options.fixed[p];
      result.status[p] = ParamStatus::kFixed;
    } else {
      problem.free.push_back(p);
      result.status[p] = ParamStatus::kFitted;
    }
  }
  result.fitted = static_cast<int>(problem.free.size());
  if (data.size() <= problem.free.size())
    throw InputError(
        fmt::format("{} measurement(s) for {} free parameter(s): need more measurements than "
                    "free parameters (or --fix some)",
                    data.size(), problem.free.size()));
  const bool relative = options.residuals == ResidualKind::kRelative;
  for (const Measurement& m : data) problem.weights.push_back(relative ? 1.0 / m.brdf : 1.0);

  result.values = problem.held;
  std::vector<double> best_x;
  if (!problem.free.empty()) {
    LocalRuns runs{problem, problem.least_squares(), result, options.progress, relative, {}};
    if (std::any_of(options.start.begin(), options.start.end(),
                    [](const auto& v) { return v.has_value(); })) {
      runs.run(start_point(problem, options), "--start");
    } else {
      const std::vector<GridStart> starts =
          powder_grid_starts(problem.grid(), options.grid_starts, result.grid_points);
      if (options.progress)
        *options.progress << fmt::format(
                                 "ochre-fit: coarse grid: {} points, {} starts (the best local minima of the "
                                 "grid, best {})\n",
                                 result.grid_points, starts.size(),
                                 problem.mean_square(starts.front().sum_of_squares, relative))
                          << std::flush;
      for (size_t s = 0; s < starts.size(); ++s)
        runs.run(starts[s].values,
                 fmt::format("grid start {} (radius {:.3g} um)", s + 1, starts[s].values[kRadius]));
    }
    result.start_runs = result.local_runs;
    best_x = choose_radius(runs, result);
    result.values = problem.values_at(best_x);
  }
  std::vector<double> residuals;
  problem.least_squares().residuals(best_x, residuals);
  for (double r : residuals) result.sum_of_squares += r * r;
  summarise_residuals(data, pigment, result);
  if (!problem.free.empty()) estimate_errors(problem, best_x, result);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

}  // namespace ochre
