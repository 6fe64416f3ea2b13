#include "spectra/white_balance.h"

#include <memory>

#include "spectra/cie.h"
#include "spectra/constant_spectrum.h"
#include "spectra/embedded_tables.h"
#include "spectra/product_spectrum.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

namespace {

constexpr std::string_view kChecker = "colorchecker_babelcolor_10nm.csv";

Array3d to_array(const XYZ& c) {
  return {c.x, c.y, c.z};
}

// x y^T added to m.
void add_outer(Mat3& m, const Array3d& x, const Array3d& y) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) += x[r] * y[c];
}

}  // namespace

const std::vector<std::string_view>& colorchecker_patch_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> n;
    const CsvTable& table = embedded_table(kChecker);
    for (size_t c = 1; c < table.column_count(); ++c) n.emplace_back(table.header()[c]);
    return n;
  }();
  return names;
}

const std::vector<SpectrumPtr>& colorchecker_patches() {
  static const std::vector<SpectrumPtr> patches = [] {
    std::vector<SpectrumPtr> p;
    const CsvTable& table = embedded_table(kChecker);
    for (size_t c = 1; c < table.column_count(); ++c) p.push_back(tabulated_spectrum(table, c));
    return p;
  }();
  return patches;
}

Mat3 white_balance_matrix(const SensorResponse& sensor, SpectrumPtr illuminant) {
  const SpectrumPtr light = normalized_to_unit_luminance(std::move(illuminant));
  const SpectrumPtr daylight = d65();
  Mat3 A{}, B{};
  for (const SpectrumPtr& patch : colorchecker_patches()) {
    const Array3d c = to_array(sensor.response_of(ProductSpectrum(patch, light)));
    const Array3d x = to_array(spectrum_to_xyz(ProductSpectrum(patch, daylight)));
    add_outer(A, c, c);
    add_outer(B, x, c);
  }
  const Mat3 A_inv = A.inverse();
  const Mat3 M0 = B * A_inv;
  const Array3d cw = to_array(sensor.response_of(*light));
  const Array3d xw = to_array(spectrum_to_xyz(*daylight));
  const Array3d a = A_inv * cw;
  const double denominator = cw[0] * a[0] + cw[1] * a[1] + cw[2] * a[2];
  const Array3d m0_cw = M0 * cw;
  Mat3 M = M0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M(r, c) += (xw[r] - m0_cw[r]) * a[c] / denominator;
  return M;
}

}  // namespace ochre
