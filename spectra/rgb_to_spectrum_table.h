#pragma once
// RGBToSpectrumTable: RGB -> sigmoid-polynomial coefficients (Jakob & Hanika 2019, section 4),
// for linear Rec.709 / sRGB primaries with D65 as the illuminant. The table is optimised at build
// time by spectra/generator/rgb2spec_opt.cpp and embedded in the library.
//
//   RGBToSpectrumTable::srgb().lookup(RGB) -> RGBSigmoidPolynomial
//     The reflectance S(c0 l^2 + c1 l + c2) under D65 has (up to the table's interpolation) the
//     colour rgb. Components are clamped to [0, 1] (NaN counts as 0). Grey inputs (r == g == b) give an
//     exactly constant spectrum (c0 = c1 = 0). Elsewhere: trilinear interpolation of the coefficients.
//
// Layout of the table: for largest component l, z = rgb[l], x = rgb[l+1]/z, y = rgb[l+2]/z
// (indices mod 3); x, y uniform over res points in [0, 1], z at the res points scale[k].

#include <vector>

#include "spectra/color_types.h"
#include "spectra/rgb_sigmoid_polynomial.h"

namespace ochre {

class RGBToSpectrumTable {
 public:
  static const RGBToSpectrumTable& srgb();

  RGBSigmoidPolynomial lookup(RGB rgb) const;
  int resolution() const { return res_; }
  // The z sample positions (increasing, from 0 to 1).
  const std::vector<float>& scale() const { return scale_; }

 private:
  RGBToSpectrumTable(int res, std::vector<float> scale, std::vector<float> coeffs)
      : res_(res), scale_(std::move(scale)), coeffs_(std::move(coeffs)) {}
  static RGBToSpectrumTable load_embedded_srgb();
  const float* cell(int l, int k, int j, int i) const;

  int res_;
  std::vector<float> scale_;
  std::vector<float> coeffs_;  // [3][res][res][res][3], indexed [l][k (z)][j (y)][i (x)][c]
};

}  // namespace ochre
