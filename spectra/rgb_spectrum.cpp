// RGB-derived spectra (see rgb_spectrum.h).

#include "spectra/rgb_spectrum.h"

#include <algorithm>
#include <limits>

#include "spectra/cie.h"
#include "spectra/non_finite.h"
#include "spectra/rgb_to_spectrum_table.h"

namespace ochre {

UnboundedRGB decompose_unbounded(RGB rgb) {
  constexpr float kLargest = std::numeric_limits<float>::max();
  for (int c = 0; c < 3; ++c) rgb[c] = nan_safe_clamp(rgb[c], 0.0f, kLargest);
  const float m = std::max({rgb.r, rgb.g, rgb.b});
  if (m == 0.0f) return {0.0f, RGBSigmoidPolynomial::constant(0.0f)};
  // rgb / (2 m) as (rgb / m) / 2: the same bits, and no overflow of 2 m for m near the largest float.
  const RGB bounded{rgb.r / m * 0.5f, rgb.g / m * 0.5f, rgb.b / m * 0.5f};
  return {std::min(2.0f * m, kLargest), RGBToSpectrumTable::srgb().lookup(bounded)};
}

RGBAlbedoSpectrum::RGBAlbedoSpectrum(RGB rgb) : poly_(RGBToSpectrumTable::srgb().lookup(rgb)) {}

RGBUnboundedSpectrum::RGBUnboundedSpectrum(RGB rgb) {
  const UnboundedRGB u = decompose_unbounded(rgb);
  scale_ = u.scale;
  poly_ = u.poly;
}

RGBIlluminantSpectrum::RGBIlluminantSpectrum(RGB rgb) : illuminant_(d65()) {
  const UnboundedRGB u = decompose_unbounded(rgb);
  scale_ = u.scale;
  poly_ = u.poly;
}

SampledSpectrum RGBIlluminantSpectrum::sample(const SampledWavelengths& lambda) const {
  SampledSpectrum s = illuminant_->sample(lambda);
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] *= scale_ * poly_.eval(lambda[i]);
  return s;
}

}  // namespace ochre
