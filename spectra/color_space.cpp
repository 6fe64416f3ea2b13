// Working colour spaces (see color_space.h).

#include "spectra/color_space.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>

#include "spectra/chromatic_adaptation.h"
#include "spectra/cie.h"
#include "spectra/rgb_primaries.h"

namespace ochre {

namespace {

struct SpaceMatrices {
  Mat3 rgb_to_xyz, xyz_to_rgb;
};

Array3d d65_white() {
  const XYZ w = spectrum_to_xyz(*d65());
  return {w.x, w.y, w.z};
}

SpaceMatrices make_matrices(ColorSpace space) {
  const Array3d white = d65_white();
  Mat3 to_xyz;
  if (space == ColorSpace::LinearRec709) {
    to_xyz = rgb_to_xyz_matrix(kRec709Primaries, white);
  } else {
    const Array3d aces_white = xy_to_xyz(kAcesWhiteXy);
    // AP1 -> XYZ(ACES white) -> Bradford -> XYZ(our D65).
    to_xyz = bradford_adaptation(aces_white, white) * rgb_to_xyz_matrix(kAP1Primaries, aces_white);
  }
  return {to_xyz, to_xyz.inverse()};
}

const SpaceMatrices& matrices(ColorSpace space) {
  static const std::array<SpaceMatrices, 2> all = {make_matrices(ColorSpace::LinearRec709),
                                                   make_matrices(ColorSpace::ACEScg)};
  return all[space == ColorSpace::LinearRec709 ? 0 : 1];
}

std::string lowercase(std::string_view s) {
  std::string r(s);
  std::transform(r.begin(), r.end(), r.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return r;
}

}  // namespace

ColorSpace parse_color_space(std::string_view name) {
  const std::string n = lowercase(name);
  if (n == "rec709" || n == "linear-rec709" || n == "srgb-linear") return ColorSpace::LinearRec709;
  if (n == "acescg") return ColorSpace::ACEScg;
  throw std::invalid_argument("unknown colour space '" + std::string(name) +
                              "' (expected one of: rec709, linear-rec709, srgb-linear, acescg)");
}

std::string_view color_space_name(ColorSpace space) {
  return space == ColorSpace::LinearRec709 ? "linear-rec709" : "acescg";
}

const Mat3& xyz_to_rgb_matrix(ColorSpace space) {
  return matrices(space).xyz_to_rgb;
}
const Mat3& rgb_to_xyz_matrix(ColorSpace space) {
  return matrices(space).rgb_to_xyz;
}

RGB xyz_to_rgb(const XYZ& xyz, ColorSpace space) {
  const Array3d v = xyz_to_rgb_matrix(space) * Array3d{xyz.x, xyz.y, xyz.z};
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

XYZ rgb_to_xyz(const RGB& rgb, ColorSpace space) {
  const Array3d v = rgb_to_xyz_matrix(space) * Array3d{rgb.r, rgb.g, rgb.b};
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// IEC 61966-2-1:1999: linear segment below 0.0031308, power 1/2.4 above. Negative values are
// encoded with odd symmetry so that out-of-gamut colours survive a round trip.
float srgb_encode(float linear) {
  const float a = std::abs(linear);
  const float e = a <= 0.0031308f ? 12.92f * a : 1.055f * std::pow(a, 1.0f / 2.4f) - 0.055f;
  return std::copysign(e, linear);
}

float srgb_decode(float encoded) {
  const float a = std::abs(encoded);
  const float l = a <= 0.04045f ? a / 12.92f : std::pow((a + 0.055f) / 1.055f, 2.4f);
  return std::copysign(l, encoded);
}

}  // namespace ochre
