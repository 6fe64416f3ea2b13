#pragma once
// Working colour spaces for output: linear Rec.709 (default) and ACEScg, both referred to our
// XYZ, in which the white is CIE D65 as integrated with our colour matching functions
// (spectrum_to_xyz(*d65())). In both spaces that white maps to RGB (1, 1, 1).
//
//   parse_color_space("rec709" | "linear-rec709" | "srgb-linear" | "acescg") -> ColorSpace
//       (case-insensitive; throws std::invalid_argument listing the accepted names)
//   color_space_name(ColorSpace) -> "linear-rec709" | "acescg"
//   xyz_to_rgb(XYZ, ColorSpace), rgb_to_xyz(RGB, ColorSpace)
//   xyz_to_rgb_matrix(ColorSpace), rgb_to_xyz_matrix(ColorSpace)   the 3x3 matrices (double)
//   srgb_encode(linear), srgb_decode(encoded)   sRGB transfer function, IEC 61966-2-1:1999
//
// Rec.709: matrix derived from the BT.709 primaries and the D65 white above (SMPTE RP 177), as
// pbrt-v4 does; it equals the textbook sRGB matrix to ~1e-4. ACEScg: matrix derived from the
// AP1 primaries and the ACES white, preceded by a Bradford adaptation from our D65 to the ACES
// white (the OCIO/ACES "AP1 to XYZ-D65 Bradford" convention).

#include <string_view>

#include "spectra/color_types.h"
#include "spectra/mat3.h"

namespace ochre {

enum class ColorSpace { LinearRec709, ACEScg };

ColorSpace parse_color_space(std::string_view name);
std::string_view color_space_name(ColorSpace space);

const Mat3& xyz_to_rgb_matrix(ColorSpace space);
const Mat3& rgb_to_xyz_matrix(ColorSpace space);
RGB xyz_to_rgb(const XYZ& xyz, ColorSpace space);
XYZ rgb_to_xyz(const RGB& rgb, ColorSpace space);

float srgb_encode(float linear);
float srgb_decode(float encoded);

}  // namespace ochre
