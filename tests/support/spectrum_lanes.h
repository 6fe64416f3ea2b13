#pragma once
// lanes({a, b, c, d}): a SampledSpectrum whose lanes repeat the given values ({a, b, c, d, a, b, c, d} for
// 8 lanes), so a test written with a few distinct per-wavelength values checks every lane whatever the
// number of hero wavelengths (kSpectrumSamples) is.

#include <initializer_list>

#include "spectra/sampled_spectrum.h"

namespace ochre::test {

inline SampledSpectrum lanes(std::initializer_list<float> values) {
  SampledSpectrum s;
  const float* v = values.begin();
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = v[i % values.size()];
  return s;
}

}  // namespace ochre::test
