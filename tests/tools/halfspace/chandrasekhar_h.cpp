#include "chandrasekhar_h.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "materials/numerics/gauss_legendre.h"

namespace ochre::halfspace::test {

ChandrasekharH::ChandrasekharH(double c, int nodes) : c_(c) {
  GaussLegendreRule rule = gauss_legendre_rule(nodes, 0.0, 1.0);  // on [0, 1]
  x_ = std::move(rule.nodes);
  w_ = std::move(rule.weights);
  h_.assign(nodes, 1.0);
  for (int iteration = 0; iteration < 10000; ++iteration) {
    double change = 0.0;
    std::vector<double> next(nodes);
    for (int i = 0; i < nodes; ++i) {
      next[i] = std::sqrt(h_[i] * (*this)(x_[i]));
      change = std::max(change, std::abs(next[i] - h_[i]));
    }
    h_ = next;
    if (change < 1e-13) break;
  }
}

double ChandrasekharH::operator()(double mu) const {
  double integral = 0.0;
  for (size_t j = 0; j < x_.size(); ++j) integral += w_[j] * x_[j] * h_[j] / (mu + x_[j]);
  return 1.0 / (std::sqrt(1.0 - c_) + 0.5 * c_ * integral);
}

}  // namespace ochre::halfspace::test
