#include "tools/vgroove/vgroove_colour.h"

#include <algorithm>

#include "renderer/image/display_image.h"
#include "spectra/cie.h"
#include "spectra/color_space.h"

namespace ochre {

namespace {

// D65 x colour matching functions at the colour wavelengths (a Riemann sum: the 10 nm step cancels in
// the normalisation by the white), and the white diffuser's XYZ.
struct ColourWeights {
  std::vector<XyzD> weights;
  XyzD white;
};

const ColourWeights& colour_weights() {
  static const ColourWeights table = [] {
    ColourWeights t;
    const SpectrumPtr illuminant = d65();
    for (double lambda : colour_wavelengths()) {
      const float l = static_cast<float>(lambda);
      const double s = illuminant->eval(l);
      t.weights.push_back({s * cie_x(l), s * cie_y(l), s * cie_z(l)});
      t.white.x += t.weights.back().x;
      t.white.y += t.weights.back().y;
      t.white.z += t.weights.back().z;
    }
    return t;
  }();
  return table;
}

// CIE 15:2004 eq 8.5-8.7: the inverse of the L*a*b* companding.
double lab_f_inverse(double f) {
  constexpr double delta = 6.0 / 29.0;
  return f > delta ? f * f * f : 3.0 * delta * delta * (f - 4.0 / 29.0);
}

}  // namespace

const std::vector<double>& colour_wavelengths() {
  static const std::vector<double> wavelengths = [] {
    std::vector<double> w;
    for (int lambda = 380; lambda <= 730; lambda += 10) w.push_back(lambda);
    return w;
  }();
  return wavelengths;
}

Lab reflectance_to_lab(std::span<const double> reflectance) {
  const ColourWeights& t = colour_weights();
  XyzD xyz;
  for (size_t i = 0; i < t.weights.size(); ++i) {
    xyz.x += reflectance[i] * t.weights[i].x;
    xyz.y += reflectance[i] * t.weights[i].y;
    xyz.z += reflectance[i] * t.weights[i].z;
  }
  return xyz_to_lab(xyz, t.white);
}

std::array<std::uint8_t, 3> lab_to_srgb8(const Lab& lab) {
  // The display's white is the sRGB (Rec.709) white, RGB (1, 1, 1).
  static const RGB kOne{1.0f, 1.0f, 1.0f};
  static const XYZ white = rgb_to_xyz(kOne, ColorSpace::LinearRec709);
  const double fy = (lab.L + 16.0) / 116.0;
  const XYZ xyz{static_cast<float>(white.x * lab_f_inverse(fy + lab.a / 500.0)),
                static_cast<float>(white.y * lab_f_inverse(fy)),
                static_cast<float>(white.z * lab_f_inverse(fy - lab.b / 200.0))};
  const RGB rgb = xyz_to_rgb(xyz, ColorSpace::LinearRec709);
  std::array<std::uint8_t, 3> out;
  for (int c = 0; c < 3; ++c) out[c] = quantize_unorm8(srgb_encode(std::clamp(rgb[c], 0.0f, 1.0f)));
  return out;
}

}  // namespace ochre
