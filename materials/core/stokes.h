#pragma once
// Stokes vectors (S0, S1, S2, S3) of one beam, always tied to a reference frame: a unit x axis
// perpendicular to the propagation direction d, with y = cross(d, x) (docs/polarization.md).
//   S0 = total intensity, S1 = x minus y linear, S2 = +45 minus -45 deg linear (+45 deg lies between
//   x and y), S3 = right minus left circular as seen by a sensor looking back at the source.
// With complex field amplitudes (time dependence exp(+i w t), the convention of eta = n - i k):
//   S2 = 2 Re(Ex conj(Ey)), S3 = -2 Im(Ex conj(Ey)).

#include <array>
#include <cmath>

#include "spectra/sampled_spectrum.h"

namespace ochre {

struct Stokes {
  std::array<float, 4> s{};

  constexpr float operator[](int i) const { return s[i]; }
  constexpr float& operator[](int i) { return s[i]; }

  static constexpr Stokes unpolarized(float intensity) { return {{intensity, 0.0f, 0.0f, 0.0f}}; }
  // Degree of polarization sqrt(S1^2 + S2^2 + S3^2) / S0 (0 for S0 = 0).
  float degree_of_polarization() const {
    if (!(s[0] > 0.0f)) return 0.0f;
    return std::sqrt(s[1] * s[1] + s[2] * s[2] + s[3] * s[3]) / s[0];
  }
};

// One Stokes vector per hero wavelength.
using StokesSpectrum = std::array<Stokes, kSpectrumSamples>;

}  // namespace ochre
