#pragma once
// The 3x3 matrix that turns a camera's R, G, B into white-balanced CIE XYZ (docs/cameras.md, "White
// balance"): a least-squares fit over the 24 patches of the X-Rite ColorChecker (BabelColor's average
// reflectances, spectra/data/colorchecker_babelcolor_10nm.csv) seen by the camera under `illuminant`, to
// the XYZ of the same patches seen by the CIE observer under D65, constrained to map the camera's response
// to a perfect white under `illuminant` exactly onto D65 white. Both illuminants are taken at luminance 1,
// so the fit keeps the exposure: a white surface of luminance Y comes out with Y.
//
// The constrained fit (each row of M independently; c_i camera RGB, x_i target XYZ, c_w, x_w the whites):
//   minimise sum_i |M c_i - x_i|^2 subject to M c_w = x_w:
//   M = M0 + (x_w - M0 c_w) (A^-1 c_w)^T / (c_w^T A^-1 c_w),  A = sum c_i c_i^T,  M0 = (sum x_i c_i^T) A^-1.

#include <string_view>
#include <vector>

#include "spectra/mat3.h"
#include "spectra/sensor_response.h"

namespace ochre {

// The reflectance spectra of the 24 ColorChecker patches, in chart order, and their names.
const std::vector<SpectrumPtr>& colorchecker_patches();
const std::vector<std::string_view>& colorchecker_patch_names();

Mat3 white_balance_matrix(const SensorResponse& sensor, SpectrumPtr illuminant);

}  // namespace ochre
