#pragma once
// The fitted model's c-dependent constants (lambert_sphere.h) of a spectrum's wavelengths, one array per
// constant (structure of arrays). A shading point builds them for each of its wavelengths: computed lane by
// lane with the library's pow() that was about half the cost of an LS lobe in a render, and a table over c
// (interpolated) cost as much again in cache misses on the cave. Computed here for all the lanes at once with
// the branchless exp and log (materials/numerics/branchless_math.h) the loop runs as vector instructions,
// without a table, and closer to the double-precision constants than the table was (within ~1e-6 relative,
// tests/materials/lobes/lambert_sphere/constant_lanes_test.cpp). A loop over the wavelengths that reads
// at(k) loads each constant for all of them at once and vectorizes too.

#include <array>
#include <span>

#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "spectra/sampled_spectrum.h"

namespace ochre {

struct LambertSphereConstantLanes {
  using Lanes = std::array<float, kSpectrumSamples>;
  Lanes c, h0_a, h0_d, inv_h0_infinity, A, B, C, D, E, F, ln_h1_at_one, l, l2_plus_45m_over_64, fast_constant,
      fast_slope;
  LambertSphereConstants<float> at(int k) const {
    return {c[k],
            h0_a[k],
            h0_d[k],
            inv_h0_infinity[k],
            A[k],
            B[k],
            C[k],
            D[k],
            E[k],
            F[k],
            ln_h1_at_one[k],
            l[k],
            l2_plus_45m_over_64[k],
            fast_constant[k],
            fast_slope[k]};
  }
  void set(int k, const LambertSphereConstants<float>& v) {
    c[k] = v.c, h0_a[k] = v.h0_a, h0_d[k] = v.h0_d, inv_h0_infinity[k] = v.inv_h0_infinity;
    A[k] = v.A, B[k] = v.B, C[k] = v.C, D[k] = v.D, E[k] = v.E, F[k] = v.F;
    ln_h1_at_one[k] = v.ln_h1_at_one, l[k] = v.l, l2_plus_45m_over_64[k] = v.l2_plus_45m_over_64;
    fast_constant[k] = v.fast_constant, fast_slope[k] = v.fast_slope;
  }
};

// lambert_sphere_constants(c[k], with_fast_variant) in single precision for every lane k (c clamped to
// [0, 1], NaN as 0).
LambertSphereConstantLanes lambert_sphere_constant_lanes(std::span<const float, kSpectrumSamples> c,
                                                         bool with_fast_variant = true);

// The full model (lambert_sphere_full) at every lane k: f[k] from at(k), for valid geometry (mu_i, mu_o > 0).
void lambert_sphere_full_lanes(const LambertSphereConstantLanes& k, const LambertSphereGeometry<float>& g,
                               std::span<float, kSpectrumSamples> f);

}  // namespace ochre
