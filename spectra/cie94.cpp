#include "spectra/cie94.h"

#include <algorithm>
#include <cmath>

namespace ochre {

double cie94(const Lab& reference, const Lab& sample, const Cie94Weights& w) {
  const double c_ref = std::hypot(reference.a, reference.b);
  const double dL = sample.L - reference.L;
  const double dC = std::hypot(sample.a, sample.b) - c_ref;
  const double da = sample.a - reference.a, db = sample.b - reference.b;
  // Rounding can make da^2 + db^2 - dC^2 slightly negative for a pure chroma difference.
  const double dH2 = std::max(0.0, da * da + db * db - dC * dC);
  const double s_c = 1.0 + w.K1 * c_ref;
  const double s_h = 1.0 + w.K2 * c_ref;
  const double l_term = dL / w.kL;  // SL = 1
  const double c_term = dC / (w.kC * s_c);
  return std::sqrt(l_term * l_term + c_term * c_term + dH2 / (w.kH * w.kH * s_h * s_h));
}

}  // namespace ochre
