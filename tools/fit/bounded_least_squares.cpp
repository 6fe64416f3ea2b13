#include "tools/fit/bounded_least_squares.h"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace ochre {

namespace {

// Central differences: error O(h^2) against round-off O(eps / h); h ~ eps^(1/3) balances them for
// coordinates of order 1 (the fitted coordinates are scaled so: powder_fit_params.h).
double difference_step(double x) {
  return 1e-6 * std::max(1.0, std::abs(x));
}

struct Objective {
  const BoundedLeastSquares* problem;
  std::vector<double> residuals;
  LocalMinimum best;
  int residual_evaluations = 0;
  int objective_evaluations = 0;

  double sum_of_squares(const std::vector<double>& x) {
    problem->residuals(x, residuals);
    ++residual_evaluations;
    double sum = 0;
    for (double r : residuals) sum += r * r;
    return std::isfinite(sum) ? sum : std::numeric_limits<double>::max();
  }

  // f = sum r^2 and, when asked, its gradient 2 J^T r.
  double evaluate(const double* x_in, double* gradient, unsigned n) {
    std::vector<double> x(x_in, x_in + n);
    const double f = sum_of_squares(x);
    if (f < best.sum_of_squares || best.x.empty()) {
      best.x = x;
      best.sum_of_squares = f;
    }
    if (gradient) {
      const std::vector<double> r = residuals;
      const Matrix j = residual_jacobian(*problem, x, &residual_evaluations);
      for (unsigned k = 0; k < n; ++k) {
        double g = 0;
        for (size_t i = 0; i < r.size(); ++i) g += 2.0 * r[i] * j[i][k];
        gradient[k] = g;
      }
    }
    ++objective_evaluations;
    if (problem->on_evaluation) problem->on_evaluation(objective_evaluations, f);
    return f;
  }

  static double callback(unsigned n, const double* x, double* gradient, void* data) {
    return static_cast<Objective*>(data)->evaluate(x, gradient, n);
  }
};

}  // namespace

namespace {

// One SLSQP run from x (clamped into the bounds), counting into `objective`; returns NLopt's status.
nlopt_result slsqp_run(const BoundedLeastSquares& problem, std::vector<double> x, Objective& objective) {
  const unsigned n = static_cast<unsigned>(x.size());
  const std::unique_ptr<nlopt_opt_s, void (*)(nlopt_opt)> opt(nlopt_create(NLOPT_LD_SLSQP, n), nlopt_destroy);
  nlopt_set_lower_bounds(opt.get(), problem.lower.data());
  nlopt_set_upper_bounds(opt.get(), problem.upper.data());
  nlopt_set_min_objective(opt.get(), &Objective::callback, &objective);
  nlopt_set_ftol_rel(opt.get(), 1e-12);
  nlopt_set_xtol_rel(opt.get(), 1e-9);
  nlopt_set_maxeval(opt.get(), 2000);
  for (unsigned k = 0; k < n; ++k) x[k] = std::clamp(x[k], problem.lower[k], problem.upper[k]);
  double f = 0;
  const nlopt_result status = nlopt_optimize(opt.get(), x.data(), &f);
  if (objective.best.x.empty()) {  // NLopt stopped before evaluating (invalid arguments)
    objective.best.x = x;
    objective.best.sum_of_squares = objective.sum_of_squares(x);
  }
  return status;
}

}  // namespace

LocalMinimum minimise_sum_of_squares(const BoundedLeastSquares& problem, const std::vector<double>& start) {
  Objective objective{&problem, {}, {}, 0, 0};
  nlopt_result status = slsqp_run(problem, start, objective);
  // SLSQP's quasi-Newton Hessian, built from finite-difference gradients, can stall in a long narrow
  // valley (the correlated parameters) and report convergence short of the minimum: restarted from its
  // best point with a fresh Hessian until the sum of squares stops falling.
  constexpr int kRestarts = 5;
  for (int restart = 0; restart < kRestarts; ++restart) {
    const double before = objective.best.sum_of_squares;
    status = slsqp_run(problem, objective.best.x, objective);
    if (!(objective.best.sum_of_squares < before * (1.0 - 1e-9))) break;
  }
  LocalMinimum result = objective.best;
  result.objective_evaluations = objective.objective_evaluations;
  result.residual_evaluations = objective.residual_evaluations;
  result.stop = nlopt_result_to_string(status);
  return result;
}

Matrix residual_jacobian(const BoundedLeastSquares& problem, const std::vector<double>& x, int* evaluations) {
  std::vector<double> plus, minus, shifted = x;
  Matrix j;
  for (size_t k = 0; k < x.size(); ++k) {
    const double h = difference_step(x[k]);
    shifted[k] = x[k] + h;
    problem.residuals(shifted, plus);
    shifted[k] = x[k] - h;
    problem.residuals(shifted, minus);
    shifted[k] = x[k];
    if (j.empty()) j.assign(plus.size(), std::vector<double>(x.size()));
    for (size_t i = 0; i < plus.size(); ++i) j[i][k] = (plus[i] - minus[i]) / (2.0 * h);
    if (evaluations) *evaluations += 2;
  }
  return j;
}

std::optional<Matrix> least_squares_covariance(const Matrix& jacobian, double sum_of_squares) {
  if (jacobian.empty()) return std::nullopt;
  const size_t m = jacobian.size(), n = jacobian[0].size();
  if (m <= n) return std::nullopt;
  // Cholesky factor L of J^T J, then its inverse column by column.
  Matrix a(n, std::vector<double>(n, 0.0));
  for (size_t r = 0; r < n; ++r)
    for (size_t c = 0; c < n; ++c)
      for (size_t i = 0; i < m; ++i) a[r][c] += jacobian[i][r] * jacobian[i][c];
  Matrix l(n, std::vector<double>(n, 0.0));
  for (size_t c = 0; c < n; ++c) {
    double d = a[c][c];
    for (size_t k = 0; k < c; ++k) d -= l[c][k] * l[c][k];
    // Relative to the diagonal: a column the residuals do not depend on, or a combination of others.
    if (!(d > 1e-13 * a[c][c])) return std::nullopt;
    l[c][c] = std::sqrt(d);
    for (size_t r = c + 1; r < n; ++r) {
      double s = a[r][c];
      for (size_t k = 0; k < c; ++k) s -= l[r][k] * l[c][k];
      l[r][c] = s / l[c][c];
    }
  }
  const double variance = sum_of_squares / double(m - n);
  // Column by column, solve L L^T x = e_col.
  Matrix covariance(n, std::vector<double>(n, 0.0));
  std::vector<double> y(n), x(n);
  for (size_t col = 0; col < n; ++col) {
    for (size_t r = 0; r < n; ++r) {
      double s = r == col ? 1.0 : 0.0;
      for (size_t k = 0; k < r; ++k) s -= l[r][k] * y[k];
      y[r] = s / l[r][r];
    }
    for (size_t r = n; r-- > 0;) {
      double s = y[r];
      for (size_t k = r + 1; k < n; ++k) s -= l[k][r] * x[k];
      x[r] = s / l[r][r];
    }
    for (size_t r = 0; r < n; ++r) covariance[r][col] = variance * x[r];
  }
  return covariance;
}

}  // namespace ochre
