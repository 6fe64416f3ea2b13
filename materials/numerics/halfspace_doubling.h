#pragma once
// Converged numerical BRDF of a homogeneous, non-emitting half space of particles with albedo c and
// a phase function given by its Legendre coefficients A_l (p = 1/(4 pi) sum A_l P_l(u), u = +1
// forward), by the adding-doubling method per azimuthal Fourier mode (van de Hulst 1980): a
// single-scattering layer of optical thickness 2^-30 is doubled until the reflection stops changing
// (about 2^32 for c = 1, where a finite layer's deficit decays only like 1/tau).
//
// The integrals over the cosine use Gauss-Legendre nodes on [0, 1]; the cosines where the result is
// wanted are added as nodes of weight 0 (they take part in no integral but every operator is
// evaluated at them exactly). Mode m kernels are divided by (S_i S_j)^m, S = sqrt(1 - mu^2): the
// reduced kernels are polynomial-smooth at mu = 1 and compose with weights mu w (1 - mu^2)^m.
//
// The result is the multiple-scattering part only (total minus the single scattering of the same
// Legendre-truncated phase function, both computed in the same way), in the BRDF convention of
// materials/lobes/lambert_sphere/lambert_sphere.h: wi, wo away from the surface, relative azimuth phi = 0
// backscatter,
//   f_ms(mu_i, mu_o, phi) = sum_m reduced[m](mu_i, mu_o) S^m cos(m phi),  S = S_i S_o,
// so a caller adds the exact single scattering of the untruncated phase function analytically.

#include <vector>

namespace ochre {

struct HalfspaceDoublingOptions {
  int quadrature_nodes = 32;  // Gauss nodes on [0, 1]
  int max_mode = 2;           // Fourier modes 0..max_mode are returned
  int max_doublings = 80;     // layer thickness up to 2^(max_doublings - 40)
};

struct HalfspaceMultipleScattering {
  std::vector<double> mu;                    // the requested cosines (each > 0)
  std::vector<std::vector<double>> reduced;  // [m][i * mu.size() + o], see above
  double optical_thickness = 0.0;            // of the last layer (diagnostic)
  double value(int m, int i, int o) const { return reduced[m][i * mu.size() + o]; }
};

// legendre_A: A_0 .. A_L (A_0 = 1 for a normalised phase function). c in [0, 1]. eval_mu: cosines > 0.
HalfspaceMultipleScattering halfspace_multiple_scattering(const std::vector<double>& legendre_A, double c,
                                                          const std::vector<double>& eval_mu,
                                                          const HalfspaceDoublingOptions& options = {});

}  // namespace ochre
