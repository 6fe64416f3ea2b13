#include "materials/numerics/mie.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ochre {

MieEfficiencies mie_efficiencies(std::complex<double> m, double x) {
  using Complex = std::complex<double>;
  MieEfficiencies out;
  // Series length (Wiscombe 1980, as in BHMIE) and the start of the downward recurrence of D_n.
  const int nstop = static_cast<int>(x + 4.0 * std::cbrt(x) + 2.0);
  const Complex y = m * x;
  const int nmx = static_cast<int>(std::max(double(nstop), std::abs(y))) + 15;
  // Logarithmic derivative D_n(mx) by downward recurrence (stable for absorbing spheres): BH Eq 4.89.
  std::vector<Complex> d(nmx + 1, Complex(0.0));
  for (int n = nmx; n >= 1; --n) d[n - 1] = double(n) / y - 1.0 / (d[n] + double(n) / y);

  // Riccati-Bessel functions psi_n(x) and chi_n(x) by upward recurrence.
  double psi0 = std::cos(x), psi1 = std::sin(x);
  double chi0 = -std::sin(x), chi1 = std::cos(x);
  Complex xi1(psi1, -chi1);
  Complex a_prev(0.0), b_prev(0.0);
  double qsca = 0.0, qext = 0.0, g = 0.0;
  Complex back(0.0);
  for (int n = 1; n <= nstop; ++n) {
    const double dn = n;
    const double psi = (2.0 * dn - 1.0) * psi1 / x - psi0;
    const double chi = (2.0 * dn - 1.0) * chi1 / x - chi0;
    const Complex xi(psi, -chi);
    // BH Eq 4.88.
    const Complex da = d[n] / m + dn / x, db = m * d[n] + dn / x;
    const Complex an = (da * psi - psi1) / (da * xi - xi1);
    const Complex bn = (db * psi - psi1) / (db * xi - xi1);
    qsca += (2.0 * dn + 1.0) * (std::norm(an) + std::norm(bn));
    qext += (2.0 * dn + 1.0) * (an.real() + bn.real());
    // Asymmetry parameter: BH Eq 4.75 split into its two sums.
    g += (2.0 * dn + 1.0) / (dn * (dn + 1.0)) * (an.real() * bn.real() + an.imag() * bn.imag());
    if (n > 1)
      g += (dn - 1.0) * (dn + 1.0) / dn *
           (a_prev.real() * an.real() + a_prev.imag() * an.imag() + b_prev.real() * bn.real() +
            b_prev.imag() * bn.imag());
    back += (2.0 * dn + 1.0) * ((n % 2 == 1) ? 1.0 : -1.0) * (an - bn);
    a_prev = an;
    b_prev = bn;
    psi0 = psi1;
    psi1 = psi;
    chi0 = chi1;
    chi1 = chi;
    xi1 = Complex(psi1, -chi1);
  }
  const double scale = 2.0 / (x * x);
  out.scattering = scale * qsca;
  out.extinction = scale * qext;
  out.backscatter = std::norm(back) / (x * x);
  out.asymmetry = qsca > 0.0 ? 2.0 * g / qsca : 0.0;
  out.terms = nstop;
  return out;
}

}  // namespace ochre
