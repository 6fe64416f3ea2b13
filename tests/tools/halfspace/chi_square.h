#pragma once
// Small statistics helpers for the half-space tests (kept here so the tests need nothing but the
// simulation library).

#include <cmath>
#include <vector>

namespace ochre::halfspace::test {

// Pearson statistic of observed against expected counts (cells expecting fewer than 5 are pooled).
struct ChiSquare {
  double statistic = 0.0;
  int degrees_of_freedom = 0;
};

inline ChiSquare chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
  ChiSquare r;
  double pooled_observed = 0.0, pooled_expected = 0.0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5.0) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      continue;
    }
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++r.degrees_of_freedom;
  }
  if (pooled_expected > 0.0) {
    r.statistic +=
        (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++r.degrees_of_freedom;
  }
  r.degrees_of_freedom -= 1;  // the counts sum to the number of samples
  return r;
}

// Standard-normal deviate of a chi-square statistic (Wilson-Hilferty 1931: (X/k)^(1/3) is close to
// normal with mean 1 - 2/(9k) and variance 2/(9k)). Large positive values reject.
inline double chi_square_z(const ChiSquare& r) {
  const double k = r.degrees_of_freedom, v = 2.0 / (9.0 * k);
  return (std::cbrt(r.statistic / k) - (1.0 - v)) / std::sqrt(v);
}

}  // namespace ochre::halfspace::test
