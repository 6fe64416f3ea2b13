#pragma once
// CIELAB and the CIEDE2000 colour difference, for comparing display-referred images (ochre-diff).
//
// CIEDE2000 follows G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference formula:
// implementation notes, supplementary test data, and mathematical observations", Color Research &
// Application 30(1), 2005, equations (1)-(22), including its conventions for achromatic colours
// (hue angle 0 when a' = b = 0, hue difference 0 and mean hue = sum when a chroma is 0).

namespace ochre {

struct Lab {
  double L = 0.0, a = 0.0, b = 0.0;
};

struct XyzD {
  double x = 0.0, y = 0.0, z = 0.0;
};

// CIE 1976 L*a*b* (CIE 15:2004, section 8.2.1) of xyz relative to the reference white.
Lab xyz_to_lab(const XyzD& xyz, const XyzD& white);

// Linear sRGB (IEC 61966-2-1 primaries, D65) to XYZ with Y(white) = 1, and the white it uses
// (the matrix applied to RGB (1, 1, 1), so that white has a* = b* = 0 exactly).
XyzD linear_srgb_to_xyz(double r, double g, double b);
XyzD srgb_d65_white();

// The CIEDE2000 difference between two colours, with the parametric factors kL = kC = kH = 1
// unless given. Symmetric in its two colours.
double ciede2000(const Lab& first, const Lab& second, double kL = 1.0, double kC = 1.0, double kH = 1.0);

}  // namespace ochre
