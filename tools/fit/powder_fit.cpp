#include "tools/fit/powder_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "renderer/input_error.h"
#include "tools/fit/powder_fit_model.h"

namespace ochre {

namespace {

// The coarse grid of the nonlinear parameters, over their bounds (log-spaced where fitted as logs).
const std::array<std::vector<double>, kPowderFitParams>& coarse_grid() {
  static const std::array<std::vector<double>, kPowderFitParams> grid = {{
      {},  // volume_amplitude: solved exactly at each grid point
      {-0.8, -0.4, 0.0, 0.4, 0.8},
      {0.02, 0.06, 0.2, 0.6, 2.0, 6.0, 20.0},
      {0.007, 0.015, 0.03, 0.06, 0.12, 0.25, 0.5, 1.0, 2.0, 4.0},
      {},  // surface_amplitude: solved exactly at each grid point
      {0.1, 0.3, 1.0, 3.0, 10.0, 30.0},
  }};
  return grid;
}

// The data, the weights and which parameters are fitted: the residuals as a function of the fitted
// coordinates.
struct FitProblem {
  const std::vector<Measurement>& data;
  const FitPigment& pigment;
  std::vector<double> weights;  // residual = weight (fit - brdf)
  PowderValues held{};          // the values of the parameters that are not fitted
  std::vector<int> free;        // fitted parameters, in order

  bool is_free(int param) const { return std::find(free.begin(), free.end(), param) != free.end(); }

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
      ls.lower.push_back(to_coordinate(p, powder_fit_specs()[p].lower));
      ls.upper.push_back(to_coordinate(p, powder_fit_specs()[p].upper));
    }
    return ls;
  }
};

// The amplitudes A_v, A_s' (within their bounds, or held) minimising sum w^2 (A_v volume + A_s' surface -
// brdf)^2 for fixed nonlinear parameters. The sum is a convex quadratic in them, so its minimum over the
// box is the unconstrained one when that lies inside, else the best one-dimensional minimum along an edge.
struct Amplitudes {
  double volume = 0, surface = 0, sum_of_squares = std::numeric_limits<double>::infinity();
};

Amplitudes best_amplitudes(const PowderParts& parts, const FitProblem& problem) {
  double vv = 0, ss = 0, vs = 0, vy = 0, sy = 0, yy = 0;
  for (size_t i = 0; i < parts.volume.size(); ++i) {
    const double w2 = problem.weights[i] * problem.weights[i];
    const double v = parts.volume[i], s = parts.surface[i], y = problem.data[i].brdf;
    vv += w2 * v * v, ss += w2 * s * s, vs += w2 * v * s;
    vy += w2 * v * y, sy += w2 * s * y, yy += w2 * y * y;
  }
  const FitParamSpec& va = powder_fit_specs()[kVolumeAmplitude];
  const FitParamSpec& sa = powder_fit_specs()[kSurfaceAmplitude];
  const bool v_free = problem.is_free(kVolumeAmplitude), s_free = problem.is_free(kSurfaceAmplitude);
  const auto best_v = [&](double s) {
    if (!v_free) return problem.held[kVolumeAmplitude];
    return vv > 0 ? std::clamp((vy - s * vs) / vv, va.lower, va.upper) : va.lower;
  };
  const auto best_s = [&](double v) {
    if (!s_free) return problem.held[kSurfaceAmplitude];
    return ss > 0 ? std::clamp((sy - v * vs) / ss, sa.lower, sa.upper) : sa.lower;
  };
  Amplitudes best;
  const auto consider = [&](double v, double s) {
    const double sse = v * v * vv + 2 * v * s * vs + s * s * ss - 2 * v * vy - 2 * s * sy + yy;
    if (sse < best.sum_of_squares) best = {v, s, sse};
  };
  for (double v : v_free ? std::vector<double>{va.lower, va.upper} : std::vector<double>{best_v(0)})
    consider(v, best_s(v));
  for (double s : s_free ? std::vector<double>{sa.lower, sa.upper} : std::vector<double>{best_s(0)})
    consider(best_v(s), s);
  const double det = vv * ss - vs * vs;
  if (v_free && s_free && det > 1e-12 * vv * ss) {
    const double v = (vy * ss - sy * vs) / det, s = (sy * vv - vy * vs) / det;
    if (v >= va.lower && v <= va.upper && s >= sa.lower && s <= sa.upper) consider(v, s);
  }
  return best;
}

struct Candidate {
  double sum_of_squares;
  PowderValues values;
};

// Every point of the coarse grid of the free nonlinear parameters (held ones stay), with its best
// amplitudes; the `count` best.
std::vector<Candidate> best_grid_points(const FitProblem& problem, int count, int& grid_points) {
  static constexpr std::array<int, 4> kNonlinear = {kAnisotropy, kKappa, kRadius, kCorrelationLength};
  std::array<std::vector<double>, 4> axes;
  for (size_t a = 0; a < kNonlinear.size(); ++a)
    axes[a] = problem.is_free(kNonlinear[a]) ? coarse_grid()[kNonlinear[a]]
                                             : std::vector<double>{problem.held[kNonlinear[a]]};
  std::vector<Candidate> candidates;
  std::array<size_t, 4> at{};
  for (;;) {
    PowderValues v = problem.held;
    for (size_t a = 0; a < kNonlinear.size(); ++a) v[kNonlinear[a]] = axes[a][at[a]];
    const Amplitudes amplitudes = best_amplitudes(powder_parts(v, problem.data, problem.pigment), problem);
    v[kVolumeAmplitude] = amplitudes.volume;
    v[kSurfaceAmplitude] = amplitudes.surface;
    candidates.push_back({amplitudes.sum_of_squares, v});
    size_t a = 0;
    while (a < at.size() && ++at[a] == axes[a].size()) at[a++] = 0;
    if (a == at.size()) break;
  }
  grid_points = static_cast<int>(candidates.size());
  const size_t keep = std::min(candidates.size(), static_cast<size_t>(std::max(count, 1)));
  std::partial_sort(candidates.begin(), candidates.begin() + keep, candidates.end(),
                    [](const Candidate& a, const Candidate& b) { return a.sum_of_squares < b.sum_of_squares; });
  candidates.resize(keep);
  return candidates;
}

// The local runs so far: the best point and the counts.
struct LocalRuns {
  const FitProblem& problem;
  const BoundedLeastSquares least_squares;
  LocalMethod method;
  PowderFitResult& result;
  std::vector<LocalMinimum> minima;

  const LocalMinimum& run(const PowderValues& start) {
    minima.push_back(minimise_sum_of_squares(least_squares, problem.coordinates_of(start), method));
    ++result.local_runs;
    result.objective_evaluations += minima.back().objective_evaluations;
    result.residual_evaluations += minima.back().residual_evaluations;
    return minima.back();
  }

  const LocalMinimum& best() const {
    return *std::min_element(minima.begin(), minima.end(), [](const LocalMinimum& a, const LocalMinimum& b) {
      return a.sum_of_squares < b.sum_of_squares;
    });
  }
};

// The model sees the radius only through the grains' albedo rho(lambda, b), which the Mie resonances of
// weakly absorbing grains make non-monotonic in b (hematite at 700 nm: rho(0.05 um) = rho(0.27 um) =
// rho(0.50 um) = 0.75). At one wavelength several radii then fit equally well. This finds them: a scan of
// the radius with the other parameters at the best fit, and a local run from each minimum of the scan that
// could come close to the best. Returns the minima found, the best fit's included.
void add_radius_alternatives(LocalRuns& runs, double variance) {
  const PowderValues best = runs.problem.values_at(runs.best().x);
  const double best_sse = runs.best().sum_of_squares;
  const FitParamSpec& spec = powder_fit_specs()[kRadius];
  constexpr int kScan = 1200;
  const double lo = std::log(spec.lower), step = (std::log(spec.upper) - lo) / (kScan - 1);
  std::vector<double> sse(kScan);
  std::vector<double> residuals;
  for (int i = 0; i < kScan; ++i) {
    PowderValues v = best;
    v[kRadius] = std::exp(lo + i * step);
    runs.least_squares.residuals(runs.problem.coordinates_of(v), residuals);
    ++runs.result.residual_evaluations;
    sse[i] = 0;
    for (double r : residuals) sse[i] += r * r;
  }
  std::vector<std::pair<double, double>> minima;  // (sse, radius)
  for (int i = 0; i < kScan; ++i) {
    const bool minimum = (i == 0 || sse[i] <= sse[i - 1]) && (i == kScan - 1 || sse[i] <= sse[i + 1]);
    const double radius = std::exp(lo + i * step);
    // Re-fitting the other parameters lowers a scan minimum by a few variances at most when it is a true
    // alternative; the best fit's own basin is already known.
    if (minimum && sse[i] <= best_sse + 25.0 * variance && std::abs(std::log(radius / best[kRadius])) > 0.02)
      minima.push_back({sse[i], radius});
  }
  std::sort(minima.begin(), minima.end());
  if (minima.size() > 8) minima.resize(8);
  for (const auto& [scan_sse, radius] : minima) {
    PowderValues start = best;
    start[kRadius] = radius;
    runs.run(start);
  }
}

// True when the fitted coordinate x of `param` lies on one of its bounds.
bool on_bound(int param, double x) {
  const FitParamSpec& s = powder_fit_specs()[param];
  const double lower = to_coordinate(param, s.lower), upper = to_coordinate(param, s.upper);
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

void summarise_residuals(const std::vector<Measurement>& data, const FitPigment& pigment, PowderFitResult& r) {
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

// Standard errors of the parameters fitted inside their bounds (those on a bound are held there).
void estimate_errors(FitProblem problem, const std::vector<double>& x, PowderFitResult& r) {
  problem.held = problem.values_at(x);
  std::vector<int> interior;
  for (size_t k = 0; k < problem.free.size(); ++k)
    if (on_bound(problem.free[k], x[k]))
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
  for (size_t k = 0; k < interior.size(); ++k)
    r.standard_error[interior[k]] =
        std::sqrt((*covariance)[k][k]) * value_per_coordinate(interior[k], problem.held[interior[k]]);
}

}  // namespace

PowderFitResult fit_powder(const std::vector<Measurement>& data, const FitPigment& pigment,
                           const PowderFitOptions& options) {
  const auto start_time = std::chrono::steady_clock::now();
  FitProblem problem{data, pigment, {}, powder_default_values(), {}};
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
    throw InputError(fmt::format("{} measurement(s) for {} free parameter(s): need more measurements than "
                                 "parameters (or --fix some)",
                                 data.size(), problem.free.size()));
  for (const Measurement& m : data)
    problem.weights.push_back(options.residuals == ResidualKind::kRelative ? 1.0 / m.brdf : 1.0);

  result.values = problem.held;
  std::vector<double> best_x;
  if (!problem.free.empty()) {
    LocalRuns runs{problem, problem.least_squares(), options.method, result, {}};
    for (const Candidate& start : best_grid_points(problem, options.starts, result.grid_points))
      runs.run(start.values);
    result.grid_starts = result.local_runs;
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
