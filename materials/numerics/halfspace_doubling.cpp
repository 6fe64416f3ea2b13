#include "materials/numerics/halfspace_doubling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "materials/core/pi.h"
#include "materials/numerics/gauss_legendre.h"

namespace ochre {

namespace {

// The first layer keeps single scattering only: its missing O(tau0) double scattering acts like an
// absorption 1 - c ~ tau0 that leaves an albedo deficit ~ sqrt(tau0) at c = 1.
constexpr int kInitialLayerExponent = 40;

// Square row-major matrix.
struct Matrix {
  int n = 0;
  std::vector<double> a;
  explicit Matrix(int n_) : n(n_), a(size_t(n_) * n_, 0.0) {}
  double& operator()(int i, int j) { return a[size_t(i) * n + j]; }
  double operator()(int i, int j) const { return a[size_t(i) * n + j]; }
};

// A diag(w) B: the composition of two kernels integrated over the quadrature.
Matrix compose(const Matrix& A, const std::vector<double>& w, const Matrix& B) {
  const int n = A.n;
  Matrix C(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      const double aw = A(i, k) * w[k];
      if (aw == 0.0) continue;
      for (int j = 0; j < n; ++j) C(i, j) += aw * B(k, j);
    }
  return C;
}

// diag(e) A (left) or A diag(e) (right): composition with the direct (unscattered) beam.
Matrix scale_rows(const Matrix& A, const std::vector<double>& e) {
  Matrix C = A;
  for (int i = 0; i < A.n; ++i)
    for (int j = 0; j < A.n; ++j) C(i, j) *= e[i];
  return C;
}
Matrix scale_columns(const Matrix& A, const std::vector<double>& e) {
  Matrix C = A;
  for (int i = 0; i < A.n; ++i)
    for (int j = 0; j < A.n; ++j) C(i, j) *= e[j];
  return C;
}

Matrix add(Matrix A, const Matrix& B) {
  for (size_t k = 0; k < A.a.size(); ++k) A.a[k] += B.a[k];
  return A;
}

// Solves (I - Q diag(w)) X = Q by LU with partial pivoting: X = Q + Q w Q + Q w Q w Q + ..., the
// repeated reflections between two layers (Q = R w R).
Matrix solve_interreflection(const Matrix& Q, const std::vector<double>& w) {
  const int n = Q.n;
  Matrix M(n), X = Q;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = (i == j ? 1.0 : 0.0) - Q(i, j) * w[j];
  std::vector<int> perm(n);
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(M(i, k)) > std::fabs(M(p, k))) p = i;
    if (M(p, k) == 0.0) throw std::runtime_error("halfspace doubling: singular interreflection matrix");
    if (p != k) {
      for (int j = 0; j < n; ++j) {
        std::swap(M(k, j), M(p, j));
        std::swap(X(k, j), X(p, j));
      }
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = M(i, k) / M(k, k);
      if (f == 0.0) continue;
      for (int j = k; j < n; ++j) M(i, j) -= f * M(k, j);
      for (int j = 0; j < n; ++j) X(i, j) -= f * X(k, j);
    }
  }
  for (int k = n - 1; k >= 0; --k)
    for (int j = 0; j < n; ++j) {
      double v = X(k, j);
      for (int i = k + 1; i < n; ++i) v -= M(k, i) * X(i, j);
      X(k, j) = v / M(k, k);
    }
  return X;
}

// Associated Legendre functions divided by (1 - x^2)^(m/2), without the Condon-Shortley phase
// (it cancels in products): Pr_m^m = (2m-1)!!, Pr_(m+1)^m = (2m+1) x Pr_m^m, then the l recurrence.
std::vector<double> reduced_associated_legendre(int m, int max_l, double x) {
  std::vector<double> p(max_l + 1, 0.0);
  if (m > max_l) return p;
  double pmm = 1.0;
  for (int k = 1; k <= m; ++k) pmm *= 2 * k - 1;
  p[m] = pmm;
  if (m + 1 <= max_l) p[m + 1] = (2 * m + 1) * x * pmm;
  for (int l = m + 2; l <= max_l; ++l) p[l] = ((2 * l - 1) * x * p[l - 1] - (l + m - 1) * p[l - 2]) / (l - m);
  return p;
}

// (l - m)! / (l + m)!
double factorial_ratio(int l, int m) {
  double r = 1.0;
  for (int k = l - m + 1; k <= l + m; ++k) r /= k;
  return r;
}

// Reduced Fourier coefficient of the phase function between propagation cosines a and b in the
// doubling convention p = sum_m (2 - delta_m0) p^m cos(m (phi_a - phi_b)):
// p^m / (S_a S_b)^m = 1/(4 pi) sum_l A_l (l-m)!/(l+m)! Pr_l^m(a) Pr_l^m(b).
double reduced_phase_mode(const std::vector<double>& A, int m, double a, double b) {
  const int L = int(A.size()) - 1;
  const std::vector<double> pa = reduced_associated_legendre(m, L, a),
                            pb = reduced_associated_legendre(m, L, b);
  double sum = 0.0;
  for (int l = m; l <= L; ++l) sum += A[l] * factorial_ratio(l, m) * pa[l] * pb[l];
  return sum / (4.0 * kPiD);
}

// (exp(-tau/a) - exp(-tau/b)) / (a - b) without cancellation (a, b > 0).
double transmission_factor(double tau, double a, double b) {
  const double x = tau * (a - b) / (a * b);
  const double ratio = std::fabs(x) < 1e-12 ? 1.0 : std::expm1(x) / x;
  return std::exp(-tau / b) * ratio * tau / (a * b);
}

}  // namespace

HalfspaceMultipleScattering halfspace_multiple_scattering(const std::vector<double>& legendre_A, double c,
                                                          const std::vector<double>& eval_mu,
                                                          const HalfspaceDoublingOptions& options) {
  const GaussLegendreRule rule = gauss_legendre_rule(options.quadrature_nodes, 0.0, 1.0);
  const int nq = options.quadrature_nodes, ne = int(eval_mu.size()), n = nq + ne;
  std::vector<double> mu(n), weight(n, 0.0);
  for (int i = 0; i < nq; ++i) {
    mu[i] = rule.nodes[i];
    weight[i] = rule.weights[i];
  }
  for (int i = 0; i < ne; ++i) mu[nq + i] = eval_mu[i];

  HalfspaceMultipleScattering out;
  out.mu = eval_mu;
  out.reduced.assign(options.max_mode + 1, std::vector<double>(size_t(ne) * ne, 0.0));

  const double tau0 = std::ldexp(1.0, -kInitialLayerExponent);
  for (int m = 0; m <= options.max_mode; ++m) {
    // Composition weights of the reduced kernels: mu w (1 - mu^2)^m.
    std::vector<double> w(n);
    for (int k = 0; k < n; ++k) w[k] = mu[k] * weight[k] * std::pow(1.0 - mu[k] * mu[k], m);
    // Single-scattering layer of thickness tau0; kernels are 2 pi f^m (reduced).
    Matrix R(n), T(n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double a = mu[i], b = mu[j];
        R(i, j) = 2.0 * kPiD * c * reduced_phase_mode(legendre_A, m, a, -b) *
                  -std::expm1(-tau0 * (1.0 / a + 1.0 / b)) / (a + b);
        T(i, j) = 2.0 * kPiD * c * reduced_phase_mode(legendre_A, m, a, b) * transmission_factor(tau0, a, b);
      }
    std::vector<double> e(n);
    for (int k = 0; k < n; ++k) e[k] = std::exp(-tau0 / mu[k]);
    double tau = tau0;
    for (int step = 0; step < options.max_doublings; ++step) {
      // Two identical layers: R2 = R + Tt (I - R R)^-1 R Tt, T2 = Tt (I - R R)^-1 Tt - E^2 with
      // Tt = T + E (diffuse plus direct); S = (I - R R)^-1 - I is diffuse.
      const Matrix S = solve_interreflection(compose(R, w, R), w);
      const Matrix X = add(R, compose(S, w, R));                          // (I + S) R
      const Matrix Y = add(compose(X, w, T), scale_columns(X, e));        // (I + S) R Tt
      const Matrix R2 = add(R, add(compose(T, w, Y), scale_rows(Y, e)));  // R + Tt Y
      const Matrix V = add(compose(S, w, T), scale_columns(S, e));        // S Tt
      const Matrix Z = add(compose(T, w, V), scale_rows(V, e));           // Tt S Tt
      Matrix T2 = add(compose(T, w, T), add(scale_columns(T, e), scale_rows(T, e)));
      T2 = add(T2, Z);
      double change = 0.0, size = 0.0;
      for (size_t k = 0; k < R.a.size(); ++k) {
        change = std::max(change, std::fabs(R2.a[k] - R.a[k]));
        size = std::max(size, std::fabs(R2.a[k]));
      }
      R = R2;
      T = T2;
      tau *= 2.0;
      // exp(-tau/mu) afresh, not by squaring: a rounded exp(-tau0/mu) squared 2^k times changes the
      // direct beam's extinction by ~1e-16 mu / tau0 relative, an energy leak at c = 1.
      for (int k = 0; k < n; ++k) e[k] = std::exp(-tau / mu[k]);
      if (change <= 1e-15 * size && tau > 1.0) break;
    }
    out.optical_thickness = tau;
    // Multiple scattering: total minus the truncated single scattering; to the relative azimuth of
    // the BRDF (cos(m (phi_rel + pi)) = (-1)^m cos(m phi_rel)) with the factor 2 - delta_m0.
    const double sign = (m % 2 == 0 ? 1.0 : -1.0) * (m == 0 ? 1.0 : 2.0);
    for (int i = 0; i < ne; ++i)
      for (int o = 0; o < ne; ++o) {
        const double a = mu[nq + i], b = mu[nq + o];
        const double total = R(nq + i, nq + o) / (2.0 * kPiD);
        const double single = c * reduced_phase_mode(legendre_A, m, a, -b) / (a + b);
        out.reduced[m][size_t(i) * ne + o] = sign * (total - single);
      }
  }
  return out;
}

}  // namespace ochre
