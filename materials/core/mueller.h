#pragma once
// Mueller matrices (4x4, float) and their algebra. Conventions (docs/polarization.md, whose 'Check
// values' tests/materials/core/mueller_test.cpp reproduces):
// - a Mueller matrix maps a Stokes vector (materials/core/stokes.h) given in one reference frame to one
//   in another; the frames belong to whoever uses the matrix (see MuellerResponse in lobe.h);
// - rotator(theta) rotates the reference FRAME (x turns by theta towards y, i.e. counter-clockwise
//   about the propagation direction), not the light;
// - rotated_element(theta, M) = rotator(-theta) M rotator(theta) is element M turned by theta
//   (e.g. a polarizer whose transmission axis is at theta from x).

#include <array>
#include <cmath>

#include "materials/core/stokes.h"
#include "materials/core/vec3.h"
#include "spectra/sampled_spectrum.h"

namespace ochre {

struct Mueller {
  std::array<std::array<float, 4>, 4> m{};
  float operator()(int r, int c) const { return m[r][c]; }
  float& operator()(int r, int c) { return m[r][c]; }

  static constexpr Mueller identity() {
    Mueller out;
    for (int i = 0; i < 4; ++i) out.m[i][i] = 1.0f;
    return out;
  }
  friend constexpr bool operator==(const Mueller&, const Mueller&) = default;
};

// One Mueller matrix per hero wavelength.
using MuellerSpectrum = std::array<Mueller, kSpectrumSamples>;

// ---------------------------------------------------------------- algebra

inline constexpr Mueller operator*(const Mueller& a, const Mueller& b) {
  Mueller out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (int k = 0; k < 4; ++k) sum += a.m[r][k] * b.m[k][c];
      out.m[r][c] = sum;
    }
  return out;
}

inline constexpr Stokes operator*(const Mueller& a, const Stokes& s) {
  Stokes out;
  for (int r = 0; r < 4; ++r)
    out.s[r] = a.m[r][0] * s.s[0] + a.m[r][1] * s.s[1] + a.m[r][2] * s.s[2] + a.m[r][3] * s.s[3];
  return out;
}

// Row vector times matrix (s^T M): how a sensor's first row propagates back along a path.
inline constexpr Stokes operator*(const Stokes& s, const Mueller& a) {
  Stokes out;
  for (int c = 0; c < 4; ++c)
    out.s[c] = s.s[0] * a.m[0][c] + s.s[1] * a.m[1][c] + s.s[2] * a.m[2][c] + s.s[3] * a.m[3][c];
  return out;
}

inline constexpr Mueller operator*(const Mueller& a, float k) {
  Mueller out = a;
  for (auto& row : out.m)
    for (float& x : row) x *= k;
  return out;
}
inline constexpr Mueller operator*(float k, const Mueller& a) {
  return a * k;
}

inline constexpr Mueller transpose(const Mueller& a) {
  Mueller out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out.m[r][c] = a.m[c][r];
  return out;
}

// Per-wavelength product and scale.
inline MuellerSpectrum operator*(const MuellerSpectrum& a, const MuellerSpectrum& b) {
  MuellerSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = a[i] * b[i];
  return out;
}
inline MuellerSpectrum operator*(const MuellerSpectrum& a, const SampledSpectrum& k) {
  MuellerSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = a[i] * k[i];
  return out;
}
inline MuellerSpectrum operator*(const MuellerSpectrum& a, float k) {
  MuellerSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = a[i] * k;
  return out;
}
// The same matrix at every wavelength.
inline MuellerSpectrum uniform_spectrum(const Mueller& a) {
  MuellerSpectrum out;
  out.fill(a);
  return out;
}
// M00 of each wavelength (the unpolarized response).
inline SampledSpectrum m00(const MuellerSpectrum& a) {
  SampledSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = a[i](0, 0);
  return out;
}

// ---------------------------------------------------------------- elements

// Ideal depolarizer with unpolarized gain f: only M00 is non-zero. Every diffuse lobe is one.
inline constexpr Mueller depolarizer(float value) {
  Mueller out;
  out.m[0][0] = value;
  return out;
}
inline MuellerSpectrum depolarizer(const SampledSpectrum& f) {
  MuellerSpectrum out{};
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = depolarizer(f[i]);
  return out;
}

// Neutral attenuation: value times the identity.
inline constexpr Mueller absorber(float value) {
  return Mueller::identity() * value;
}

// Ideal linear polarizer with its transmission axis along x (the frame's "horizontal").
inline constexpr Mueller linear_polarizer(float transmittance = 1.0f) {
  const float h = 0.5f * transmittance;
  Mueller out;
  out.m[0][0] = out.m[0][1] = out.m[1][0] = out.m[1][1] = h;
  return out;
}

// Linear retarder, fast axis along x, retardance `phase` (radians) of y behind x. With the Jones
// matrix diag(1, exp(-i phase)) and S3 = -2 Im(Ex conj(Ey)) (materials/core/stokes.h) the lower block is
// [[cos, sin], [-sin, cos]]: a quarter-wave plate maps [1,0,1,0] to [1,0,0,-1] (the note's value).
inline Mueller linear_retarder(float phase) {
  const float c = std::cos(phase), s = std::sin(phase);
  Mueller out;
  out.m[0][0] = out.m[1][1] = 1.0f;
  out.m[2][2] = out.m[3][3] = c;
  out.m[2][3] = s;
  out.m[3][2] = -s;
  return out;
}

// Re-expresses a Stokes vector in the frame whose x axis is the old one turned by theta towards y:
// S1' = cos2t S1 + sin2t S2, S2' = -sin2t S1 + cos2t S2 (a beam polarized at psi from the old x is at
// psi - theta from the new one).
inline Mueller rotator(float theta) {
  const float c = std::cos(2.0f * theta), s = std::sin(2.0f * theta);
  Mueller out;
  out.m[0][0] = out.m[3][3] = 1.0f;
  out.m[1][1] = out.m[2][2] = c;
  out.m[1][2] = s;
  out.m[2][1] = -s;
  return out;
}

// Element M (given in its own frame) turned by theta about the propagation direction: the input is
// taken into the element's frame, transformed, and brought back.
inline Mueller rotated_element(float theta, const Mueller& element) {
  return rotator(-theta) * element * rotator(theta);
}

// The angle from x_from to x_to about the propagation direction d (positive towards
// y_from = cross(d, x_from)); both axes perpendicular to d. atan2 of the components of x_to on
// (x_from, y_from) is continuous in all arguments (no branch on a coordinate's sign; see the note's
// "discontinuous reference frames" hazard) and exact for d along a coordinate axis.
inline float stokes_frame_angle(const Vec3& d, const Vec3& x_from, const Vec3& x_to) {
  const Vec3 y_from = cross(d, x_from);
  return std::atan2(dot(x_to, y_from), dot(x_to, x_from));
}

// The rotator that re-expresses the Stokes vector of light propagating along d, given in the frame
// whose x axis is x_from, in the frame whose x axis is x_to (y = cross(d, x) in both).
inline Mueller stokes_basis_rotation(const Vec3& d, const Vec3& x_from, const Vec3& x_to) {
  return rotator(stokes_frame_angle(d, x_from, x_to));
}

// The same element expressed in other frames: m maps Stokes vectors of the beam along d_in (frame x
// axis in_x) to those of the beam along d_out (axis out_x); the result does the same between the
// frames with x axes new_in_x and new_out_x: R(out_x -> new_out_x) m R(new_in_x -> in_x).
inline Mueller reframe_mueller(const Mueller& m, const Vec3& d_in, const Vec3& in_x, const Vec3& new_in_x,
                               const Vec3& d_out, const Vec3& out_x, const Vec3& new_out_x) {
  return stokes_basis_rotation(d_out, out_x, new_out_x) * m * stokes_basis_rotation(d_in, new_in_x, in_x);
}

// Per-wavelength application to a Stokes vector per wavelength.
inline StokesSpectrum operator*(const MuellerSpectrum& m, const StokesSpectrum& s) {
  StokesSpectrum out;
  for (int i = 0; i < kSpectrumSamples; ++i) out[i] = m[i] * s[i];
  return out;
}

}  // namespace ochre
