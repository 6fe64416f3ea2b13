#pragma once
// Lorenz-Mie scattering by a homogeneous sphere (Bohren and Huffman, "Absorption and Scattering of Light by
// Small Particles", 1983, Appendix A, BHMIE): efficiencies and the asymmetry parameter of a sphere of size
// parameter x = 2 pi r / lambda (r and lambda in the host medium) and relative refractive index
// m = n + i k (k >= 0 absorbs; Bohren and Huffman's exp(-i w t) convention).

#include <complex>

namespace ochre {

struct MieEfficiencies {
  double extinction = 0.0;   // Q_ext
  double scattering = 0.0;   // Q_sca
  double backscatter = 0.0;  // Q_back
  double asymmetry = 0.0;    // g = <cos Theta>
  int terms = 0;             // series terms summed (Wiscombe's criterion)

  // Single-scattering albedo Q_sca / Q_ext (0 when nothing is extinguished).
  double albedo() const { return extinction > 0.0 ? scattering / extinction : 0.0; }
};

// x > 0, finite; m with Re(m) > 0.
MieEfficiencies mie_efficiencies(std::complex<double> m, double x);

}  // namespace ochre
