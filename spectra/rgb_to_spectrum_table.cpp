// Lookup in the embedded RGB -> spectrum table (see rgb_to_spectrum_table.h).

#include "spectra/rgb_to_spectrum_table.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>

#include "spectra/non_finite.h"

namespace ochre {

namespace detail {
// Defined in the generated rgb2spec_srgb_blob.cpp: the bytes written by ochre_rgb2spec_opt.
std::span<const unsigned char> rgb2spec_srgb_blob();
}  // namespace detail

namespace {

constexpr char kMagic[16] = "ochre-rgb2spec";

template <typename T>
std::vector<T> read_array(std::span<const unsigned char> bytes, std::size_t offset, std::size_t count) {
  if (offset + count * sizeof(T) > bytes.size())
    throw std::logic_error("embedded RGB -> spectrum table is truncated");
  std::vector<T> v(count);
  std::memcpy(v.data(), bytes.data() + offset, count * sizeof(T));
  return v;
}

}  // namespace

RGBToSpectrumTable RGBToSpectrumTable::load_embedded_srgb() {
  const auto blob = detail::rgb2spec_srgb_blob();
  if (blob.size() < 24 || std::memcmp(blob.data(), kMagic, sizeof kMagic) != 0)
    throw std::logic_error("embedded RGB -> spectrum table has a bad header");
  const auto header = read_array<std::int32_t>(blob, 16, 2);
  const int res = header[0];
  if (res < 2 || res > 1024) throw std::logic_error("embedded RGB -> spectrum table has a bad resolution");
  const std::size_t n = std::size_t(res);
  auto scale = read_array<float>(blob, 24, n);
  auto coeffs = read_array<float>(blob, 24 + n * sizeof(float), 9 * n * n * n);
  return RGBToSpectrumTable(res, std::move(scale), std::move(coeffs));
}

const RGBToSpectrumTable& RGBToSpectrumTable::srgb() {
  static const RGBToSpectrumTable table = load_embedded_srgb();
  return table;
}

const float* RGBToSpectrumTable::cell(int l, int k, int j, int i) const {
  return &coeffs_[3 * (((std::size_t(l) * res_ + k) * res_ + j) * res_ + i)];
}

RGBSigmoidPolynomial RGBToSpectrumTable::lookup(RGB rgb) const {
  for (int c = 0; c < 3; ++c)
    rgb[c] = nan_safe_clamp(rgb[c], 0.0f, 1.0f);  // NaN -> 0: x, y, z index the table
  if (rgb.r == rgb.g && rgb.g == rgb.b) return RGBSigmoidPolynomial::constant(rgb.r);

  // Largest component and the two others as ratios (first maximum on ties).
  const int l = (rgb.r >= rgb.g && rgb.r >= rgb.b) ? 0 : (rgb.g >= rgb.b ? 1 : 2);
  const float z = rgb[l];
  const float x = rgb[(l + 1) % 3] / z * float(res_ - 1), y = rgb[(l + 2) % 3] / z * float(res_ - 1);
  const int xi = std::min(int(x), res_ - 2), yi = std::min(int(y), res_ - 2);
  const int zi =
      std::clamp(int(std::upper_bound(scale_.begin(), scale_.end(), z) - scale_.begin()) - 1, 0, res_ - 2);
  const float dx = x - float(xi), dy = y - float(yi), dz = (z - scale_[zi]) / (scale_[zi + 1] - scale_[zi]);

  float c[3];
  for (int n = 0; n < 3; ++n) {
    auto lerp = [](float t, float a, float b) { return a + t * (b - a); };
    auto at = [&](int dk, int dj, int di) { return cell(l, zi + dk, yi + dj, xi + di)[n]; };
    c[n] = lerp(dz, lerp(dy, lerp(dx, at(0, 0, 0), at(0, 0, 1)), lerp(dx, at(0, 1, 0), at(0, 1, 1))),
                lerp(dy, lerp(dx, at(1, 0, 0), at(1, 0, 1)), lerp(dx, at(1, 1, 0), at(1, 1, 1))));
  }
  return {c[0], c[1], c[2]};
}

}  // namespace ochre
