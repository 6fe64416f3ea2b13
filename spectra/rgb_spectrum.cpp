// RGB-derived spectra (see rgb_spectrum.h).

#include "spectra/rgb_spectrum.h"

#include <algorithm>

#include "spectra/cie.h"
#include "spectra/rgb_to_spectrum_table.h"

namespace ochre {

namespace {

RGB clamp_negative(RGB rgb) {
  for (int c = 0; c < 3; ++c) rgb[c] = std::max(rgb[c], 0.0f);  // also maps NaN to 0
  return rgb;
}

// pbrt-v4's decomposition: a spectrum bounded by 1 of colour rgb / (2 max) times the scale 2 max.
// The factor 2 puts the largest component at 0.5, the middle of the sigmoid's range, where the
// fit is smoothest; a grey rgb then gives the constant 0.5 exactly.
float unbounded_scale(const RGB& rgb) {
  return 2.0f * std::max({rgb.r, rgb.g, rgb.b});
}

RGBSigmoidPolynomial unbounded_polynomial(const RGB& rgb, float scale) {
  if (scale == 0.0f) return RGBSigmoidPolynomial::constant(0.0f);
  return RGBToSpectrumTable::srgb().lookup({rgb.r / scale, rgb.g / scale, rgb.b / scale});
}

}  // namespace

RGBAlbedoSpectrum::RGBAlbedoSpectrum(RGB rgb) : poly_(RGBToSpectrumTable::srgb().lookup(rgb)) {}

RGBUnboundedSpectrum::RGBUnboundedSpectrum(RGB rgb)
    : scale_(unbounded_scale(clamp_negative(rgb))),
      poly_(unbounded_polynomial(clamp_negative(rgb), scale_)) {}

RGBIlluminantSpectrum::RGBIlluminantSpectrum(RGB rgb)
    : scale_(unbounded_scale(clamp_negative(rgb))),
      poly_(unbounded_polynomial(clamp_negative(rgb), scale_)),
      illuminant_(d65()) {}

SampledSpectrum RGBIlluminantSpectrum::sample(const SampledWavelengths& lambda) const {
  SampledSpectrum s = illuminant_->sample(lambda);
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] *= scale_ * poly_.eval(lambda[i]);
  return s;
}

}  // namespace ochre
