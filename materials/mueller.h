#pragma once
// Minimal Mueller-matrix types the lobe interface needs today. The full Stokes/Mueller algebra
// (rotators, Fresnel Mueller matrices, frames) arrives with polarization tracing (issue 4);
// lobes already declare whether they polarize and return a Mueller matrix per wavelength.

#include <array>

#include "spectra/sampled_spectrum.h"

namespace ochre {

struct Mueller {
  std::array<std::array<float, 4>, 4> m{};
  float operator()(int r, int c) const { return m[r][c]; }
  float& operator()(int r, int c) { return m[r][c]; }
};

// One Mueller matrix per hero wavelength.
using MuellerSpectrum = std::array<Mueller, kSpectrumSamples>;

// Ideal depolarizer with unpolarized gain f: only M00 is non-zero. Every diffuse lobe is one.
inline MuellerSpectrum depolarizer(const SampledSpectrum& f) {
  MuellerSpectrum out{};
  for (int i = 0; i < kSpectrumSamples; ++i) out[i](0, 0) = f[i];
  return out;
}

}  // namespace ochre
