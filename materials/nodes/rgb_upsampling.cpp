#include "materials/nodes/rgb_upsampling.h"

#include <algorithm>

#include "spectra/cie.h"
#include "spectra/rgb_to_spectrum_table.h"

namespace ochre {

namespace {

RGB non_negative(const RGB& c) {
  return {std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)};
}

// pbrt-v4's unbounded decomposition (see spectra/rgb_spectrum.cpp): scale = 2 max(rgb), and the
// bounded spectrum of colour rgb / scale, whose largest component sits mid-range of the sigmoid.
SampledSpectrum unbounded(const RGB& rgb, const SampledWavelengths& lambda) {
  const float scale = 2.0f * std::max({rgb.r, rgb.g, rgb.b});
  SampledSpectrum s(0.0f);
  if (scale == 0.0f) return s;
  const RGBSigmoidPolynomial poly =
      RGBToSpectrumTable::srgb().lookup({rgb.r / scale, rgb.g / scale, rgb.b / scale});
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = scale * poly.eval(lambda[i]);
  return s;
}

void to_reflectance(const NodeArgs& a) {
  a.set_spectrum(0, upsample_reflectance(a.in_colour(0), a.lambda()));
}
void to_illuminant(const NodeArgs& a) {
  a.set_spectrum(0, upsample_illuminant(a.in_colour(0), a.lambda()));
}

}  // namespace

SampledSpectrum upsample_reflectance(const RGB& colour, const SampledWavelengths& lambda) {
  const RGB rgb = non_negative(colour);
  if (std::max({rgb.r, rgb.g, rgb.b}) > 1.0f) return unbounded(rgb, lambda);
  const RGBSigmoidPolynomial poly = RGBToSpectrumTable::srgb().lookup(rgb);
  SampledSpectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = poly.eval(lambda[i]);
  return s;
}

SampledSpectrum upsample_illuminant(const RGB& colour, const SampledWavelengths& lambda) {
  static const SpectrumPtr white = d65();  // luminance 1, so RGB (1,1,1) has luminance 1
  return unbounded(non_negative(colour), lambda) * white->sample(lambda);
}

NodeFn colour_to_spectrum_kernel(SpectralRole role) {
  return role == SpectralRole::kIlluminant ? to_illuminant : to_reflectance;
}

}  // namespace ochre
