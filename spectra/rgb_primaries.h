#pragma once
// RGB colour spaces from their primaries and white point (header-only: the build-time table
// generator uses it as well as the library).
//
//   xy_to_xyz({x, y}, Y = 1)               chromaticity -> XYZ with the given luminance
//   rgb_to_xyz_matrix(primaries, white)    M with XYZ = M rgb and M (1,1,1) = white
//   kRec709Primaries, kAP1Primaries, kAcesWhiteXy
// Method: SMPTE RP 177-1993 ("Derivation of basic television color equations"): the columns of M
// are the primaries' XYZ scaled so that they sum to the white.

#include "spectra/mat3.h"

namespace ochre {

struct Chromaticity {
  double x, y;
};

struct RGBPrimaries {
  Chromaticity red, green, blue;
};

// ITU-R BT.709-6 (also the sRGB primaries, IEC 61966-2-1).
inline constexpr RGBPrimaries kRec709Primaries{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
// ACES AP1 primaries (ACEScg), SMPTE ST 2065-1 / Academy S-2014-004.
inline constexpr RGBPrimaries kAP1Primaries{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}};
// ACES white point (approximately D60), Academy S-2014-004.
inline constexpr Chromaticity kAcesWhiteXy{0.32168, 0.33767};

inline constexpr Array3d xy_to_xyz(Chromaticity c, double luminance = 1.0) {
  return {c.x / c.y * luminance, luminance, (1.0 - c.x - c.y) / c.y * luminance};
}

inline Mat3 rgb_to_xyz_matrix(const RGBPrimaries& p, const Array3d& white_xyz) {
  const Array3d r = xy_to_xyz(p.red), g = xy_to_xyz(p.green), b = xy_to_xyz(p.blue);
  const Mat3 unscaled{{r[0], g[0], b[0], r[1], g[1], b[1], r[2], g[2], b[2]}};
  const Array3d s = unscaled.inverse() * white_xyz;
  return unscaled * Mat3::diagonal(s[0], s[1], s[2]);
}

}  // namespace ochre
