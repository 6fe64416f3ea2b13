#include "materials/nodes/rgb_upsampling.h"

#include <algorithm>

#include "spectra/cie.h"
#include "spectra/rgb_spectrum.h"
#include "spectra/rgb_to_spectrum_table.h"

namespace ochre {

namespace {

// The unbounded spectrum (spectra/rgb_spectrum.h): scale x the bounded spectrum of rgb / scale.
SampledSpectrum unbounded(const RGB& rgb, const SampledWavelengths& lambda) {
  const UnboundedRGB u = decompose_unbounded(rgb);
  SampledSpectrum s(0.0f);
  if (u.scale == 0.0f) return s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = u.scale * u.poly.eval(lambda[i]);
  return s;
}

void to_reflectance(const NodeArgs& a) {
  a.set_spectrum(0, upsample_reflectance(a.in_colour(0), a.lambda()));
}
void to_illuminant(const NodeArgs& a) {
  a.set_spectrum(0, upsample_illuminant(a.in_colour(0), a.lambda()));
}

}  // namespace

SampledSpectrum upsample_reflectance(const RGB& rgb, const SampledWavelengths& lambda) {
  if (std::max({rgb.r, rgb.g, rgb.b}) > 1.0f) return unbounded(rgb, lambda);
  const RGBSigmoidPolynomial poly = RGBToSpectrumTable::srgb().lookup(rgb);  // clamps to [0, 1]
  SampledSpectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = poly.eval(lambda[i]);
  return s;
}

SampledSpectrum upsample_illuminant(const RGB& colour, const SampledWavelengths& lambda) {
  static const SpectrumPtr white = d65();  // luminance 1, so RGB (1,1,1) has luminance 1
  return unbounded(colour, lambda) * white->sample(lambda);
}

NodeFn colour_to_spectrum_kernel(SpectralRole role) {
  return role == SpectralRole::kIlluminant ? to_illuminant : to_reflectance;
}

}  // namespace ochre
