// CIE 1931 colour matching functions and spectrum -> XYZ integration (see cie.h).

#include "spectra/cie.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "spectra/embedded_tables.h"

namespace ochre {

namespace {

constexpr int kCmfFirst = 360;
constexpr int kCmfCount = 471;  // 360..830 nm at 1 nm

struct CmfTable {
  std::array<float, kCmfCount> x, y, z;
};

CmfTable load_cmf_table() {
  const CsvTable& table = embedded_table("cie1931_2deg_1nm.csv");
  const auto& lambda = table.wavelengths();
  if (table.row_count() != kCmfCount || lambda.front() != kCmfFirst ||
      lambda.back() != kCmfFirst + kCmfCount - 1)
    throw std::logic_error(table.source() + ": expected 1 nm rows from 360 to 830 nm");
  CmfTable t;
  const auto &x = table.column("xbar"), &y = table.column("ybar"), &z = table.column("zbar");
  for (int i = 0; i < kCmfCount; ++i) {
    t.x[i] = static_cast<float>(x[i]);
    t.y[i] = static_cast<float>(y[i]);
    t.z[i] = static_cast<float>(z[i]);
  }
  return t;
}

const CmfTable& cmf() {
  static const CmfTable table = load_cmf_table();
  return table;
}

float interpolate(const std::array<float, kCmfCount>& v, float lambda_nm) {
  if (!(lambda_nm >= kLambdaMin && lambda_nm <= kLambdaMax)) return 0.0f;
  const float offset = lambda_nm - kCmfFirst;
  const int i = std::min(static_cast<int>(offset), kCmfCount - 2);
  const float t = offset - static_cast<float>(i);
  return v[i] + t * (v[i + 1] - v[i]);
}

}  // namespace

float cie_x(float lambda_nm) {
  return interpolate(cmf().x, lambda_nm);
}
float cie_y(float lambda_nm) {
  return interpolate(cmf().y, lambda_nm);
}
float cie_z(float lambda_nm) {
  return interpolate(cmf().z, lambda_nm);
}

XYZ spectrum_to_xyz(const Spectrum& s) {
  const CmfTable& t = cmf();
  double x = 0.0, y = 0.0, z = 0.0;
  for (int i = 0; i < kCmfCount; ++i) {
    const double v = s.eval(static_cast<float>(kCmfFirst + i));
    x += v * t.x[i];
    y += v * t.y[i];
    z += v * t.z[i];
  }
  return {static_cast<float>(x / kCieYIntegral), static_cast<float>(y / kCieYIntegral),
          static_cast<float>(z / kCieYIntegral)};
}

XYZ sampled_to_xyz(const SampledSpectrum& L, const SampledWavelengths& lambda) {
  const CmfTable& t = cmf();
  float x = 0.0f, y = 0.0f, z = 0.0f;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float pdf = lambda.pdf()[i];
    if (pdf == 0.0f) continue;
    const float w = L[i] / pdf;
    x += w * interpolate(t.x, lambda[i]);
    y += w * interpolate(t.y, lambda[i]);
    z += w * interpolate(t.z, lambda[i]);
  }
  const float norm = 1.0f / (kSpectrumSamples * kCieYIntegral);
  return {x * norm, y * norm, z * norm};
}

}  // namespace ochre
