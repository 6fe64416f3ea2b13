#pragma once
// RGBSigmoidPolynomial: the smooth bounded spectrum of Jakob & Hanika 2019, "A Low-Dimensional
// Function Space for Efficient Spectral Upsampling" (Computer Graphics Forum 38(2)), eq. 3-4:
//   f(lambda) = S(c0 lambda^2 + c1 lambda + c2),   S(x) = 1/2 + x / (2 sqrt(1 + x^2)),
// lambda in nm. Values lie in [0, 1]. A constant spectrum v has c0 = c1 = 0 and
// c2 = sigmoid_inverse(v), which is -inf for v = 0 and +inf for v = 1 (S(-inf) = 0, S(inf) = 1).
//
//   eval(lambda_nm), max_value() (exact maximum over [360, 830] nm),
//   RGBSigmoidPolynomial::sigmoid(x), RGBSigmoidPolynomial::constant(v)

#include <algorithm>
#include <cmath>
#include <limits>

#include "spectra/sampled_wavelengths.h"

namespace ochre {

struct RGBSigmoidPolynomial {
  float c0 = 0.0f, c1 = 0.0f, c2 = 0.0f;

  static float sigmoid(float x) {
    // Beyond 1e10, 1 - S(x) = 1/(4x^2) + ... is below float resolution, and x*x would overflow.
    if (!(std::abs(x) < 1e10f)) return std::isnan(x) ? x : (x > 0.0f ? 1.0f : 0.0f);
    return 0.5f + x / (2.0f * std::sqrt(1.0f + x * x));
  }

  // The polynomial whose spectrum is the constant v (clamped to [0, 1]).
  static RGBSigmoidPolynomial constant(float v) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    if (!(v > 0.0f)) return {0.0f, 0.0f, -inf};
    if (v >= 1.0f) return {0.0f, 0.0f, inf};
    const double vd = v;
    return {0.0f, 0.0f, static_cast<float>((vd - 0.5) / std::sqrt(vd * (1.0 - vd)))};
  }

  float polynomial(float lambda_nm) const {
    // c0 = c1 = 0 with an infinite c2 must give c2, not NaN: keep the Horner form.
    return (c0 * lambda_nm + c1) * lambda_nm + c2;
  }

  // Outside 360-830 nm (the range the coefficients were fitted over; a camera sensor may reach further,
  // docs/cameras.md) the spectrum holds its end values instead of following the parabola.
  float eval(float lambda_nm) const { return sigmoid(polynomial(std::clamp(lambda_nm, 360.0f, 830.0f))); }

  // S is increasing, so the maximum is S of the polynomial's maximum over [360, 830] nm: at an end
  // of the range or at the vertex of a downward parabola. Evaluated in double: the float terms
  // of the polynomial cancel (eval() itself is accurate to ~1e-5).
  float max_value() const {
    const auto poly = [&](double l) { return (double(c0) * l + c1) * l + c2; };
    double p = std::max(poly(kLambdaMin), poly(kLambdaMax));
    if (c0 < 0.0f) {
      const double vertex = -double(c1) / (2.0 * c0);
      if (vertex > kLambdaMin && vertex < kLambdaMax) p = std::max(p, poly(vertex));
    }
    return sigmoid(static_cast<float>(p));
  }
};

}  // namespace ochre
