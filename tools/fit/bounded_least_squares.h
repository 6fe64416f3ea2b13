#pragma once
// Bounded nonlinear least squares with NLopt (Johnson, "The NLopt nonlinear-optimization package",
// https://github.com/stevengj/nlopt): minimise sum_i r_i(x)^2 over lower <= x <= upper from a start point,
// with SLSQP (Kraft 1988, the method the powder paper used through scipy) on gradients 2 J^T r from
// central finite differences of the residuals. Also the Jacobian and the covariance of the estimate at a
// minimum.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ochre {

using Matrix = std::vector<std::vector<double>>;

struct BoundedLeastSquares {
  // Fills `residuals` (resized by the callee) for the point x.
  std::function<void(const std::vector<double>& x, std::vector<double>& residuals)> residuals;
  std::vector<double> lower, upper;
  // Called after each objective evaluation (NLopt's count, from 1) with its sum of squares; may be empty.
  std::function<void(int evaluation, double sum_of_squares)> on_evaluation;
};

struct LocalMinimum {
  std::vector<double> x;
  double sum_of_squares = 0;
  int objective_evaluations = 0;  // NLopt's count (each with its gradient)
  int residual_evaluations = 0;   // every evaluation of the residuals, finite differences included
  std::string stop;               // NLopt's reason
};

// The best point NLopt visited (SLSQP may end with a round-off status after converging).
LocalMinimum minimise_sum_of_squares(const BoundedLeastSquares& problem, const std::vector<double>& start);

// J[i][j] = d r_i / d x_j by central differences; `evaluations` counts the residual evaluations.
Matrix residual_jacobian(const BoundedLeastSquares& problem, const std::vector<double>& x,
                         int* evaluations = nullptr);

// The covariance of least-squares estimates, s^2 (J^T J)^-1 with s^2 = sum_of_squares / (residuals -
// parameters), or nothing when J^T J is not positive definite (the data do not determine a parameter).
std::optional<Matrix> least_squares_covariance(const Matrix& jacobian, double sum_of_squares);

}  // namespace ochre
