#include "materials/lobes/lambert_sphere/lambert_sphere_constants_table.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "spectra/non_finite.h"

namespace ochre {

namespace {

constexpr int kCells = 2048;

// The constants at s = i / kCells, computed in double and stored as floats.
const std::array<LambertSphereConstants<float>, kCells + 1>& table() {
  static const auto values = [] {
    std::array<LambertSphereConstants<float>, kCells + 1> t;
    for (int i = 0; i <= kCells; ++i) {
      const double s = static_cast<double>(i) / kCells;
      const LambertSphereConstants<double> k = lambert_sphere_constants(1.0 - s * s);
      t[i] = {static_cast<float>(k.c),
              static_cast<float>(k.h0_a),
              static_cast<float>(k.h0_d),
              static_cast<float>(k.inv_h0_infinity),
              static_cast<float>(k.A),
              static_cast<float>(k.B),
              static_cast<float>(k.C),
              static_cast<float>(k.D),
              static_cast<float>(k.E),
              static_cast<float>(k.F),
              static_cast<float>(k.ln_h1_at_one),
              static_cast<float>(k.l),
              static_cast<float>(k.l2_plus_45m_over_64),
              static_cast<float>(k.fast_constant),
              static_cast<float>(k.fast_slope)};
    }
    return t;
  }();
  return values;
}

float lerp(float a, float b, float t) {
  return a + (b - a) * t;
}

}  // namespace

LambertSphereConstants<float> lambert_sphere_constants_interpolated(float c_in) {
  const float c = nan_safe_clamp(c_in, 0.0f, 1.0f);  // NaN -> 0: c gives the index
  const float x = std::sqrt(1.0f - c) * kCells;
  const int i = std::min(static_cast<int>(x), kCells - 1);
  const float t = x - static_cast<float>(i);
  const LambertSphereConstants<float>& a = table()[i];
  const LambertSphereConstants<float>& b = table()[i + 1];
  LambertSphereConstants<float> k;
  k.c = c;  // exact: the linear terms (A, E, fast_slope...) are interpolated, c itself need not be
  k.h0_a = lerp(a.h0_a, b.h0_a, t);
  k.h0_d = lerp(a.h0_d, b.h0_d, t);
  k.inv_h0_infinity = lerp(a.inv_h0_infinity, b.inv_h0_infinity, t);
  k.A = lerp(a.A, b.A, t);
  k.B = lerp(a.B, b.B, t);
  k.C = lerp(a.C, b.C, t);
  k.D = lerp(a.D, b.D, t);
  k.E = lerp(a.E, b.E, t);
  k.F = lerp(a.F, b.F, t);
  k.ln_h1_at_one = lerp(a.ln_h1_at_one, b.ln_h1_at_one, t);
  k.l = lerp(a.l, b.l, t);
  k.l2_plus_45m_over_64 = lerp(a.l2_plus_45m_over_64, b.l2_plus_45m_over_64, t);
  k.fast_constant = lerp(a.fast_constant, b.fast_constant, t);
  k.fast_slope = lerp(a.fast_slope, b.fast_slope, t);
  return k;
}

}  // namespace ochre
