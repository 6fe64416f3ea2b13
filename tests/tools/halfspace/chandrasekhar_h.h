#pragma once
// Chandrasekhar's H function for isotropic scattering with single-scattering albedo c, the exact
// reference for the half-space BRDF f = c H(mu_i) H(mu_o) / (4 pi (mu_i + mu_o)) (Chandrasekhar 1960,
// "Radiative Transfer"; d'Eon Eq 21). Solved numerically in the form
//   1 / H(mu) = sqrt(1 - c) + (c / 2) int_0^1 x H(x) / (mu + x) dx,
// which follows from Eq 20 with Psi = c / 2 and the identity int_0^1 Psi H = 1 - sqrt(1 - c). At c = 1
// the plain iteration H <- T(H) maps k H to H / k and cycles; the geometric mean H <- sqrt(H T(H))
// removes that scale mode and converges.

#include <vector>

namespace ochre::halfspace::test {

class ChandrasekharH {
 public:
  explicit ChandrasekharH(double c, int nodes = 96);
  double operator()(double mu) const;

 private:
  double c_;
  std::vector<double> x_, w_, h_;  // Gauss-Legendre nodes and weights on [0, 1], H at the nodes
};

}  // namespace ochre::halfspace::test
