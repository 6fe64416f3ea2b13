#pragma once
// MemoizedSpectrum: a spectrum that does not depend on the shading point (a point, spot or sphere light's
// intensity, a material's pre-built spectrum), sampled once per thread for a path's wavelengths and then read
// from the thread's memo (wavelength_memo.h): a path asks for it at every light sample, and a blackbody costs
// an exp and a pow per wavelength. The values are those of Spectrum::sample, so images do not change.

#include <cstdint>

#include "spectra/spectrum.h"
#include "spectra/wavelength_memo.h"

namespace ochre {

class MemoizedSpectrum {
 public:
  // A new key each time: a light given a new spectrum (a flame's next frame) never reads the old values.
  explicit MemoizedSpectrum(SpectrumPtr spectrum)
      : spectrum_(std::move(spectrum)), key_(new_wavelength_memo_key()) {}

  const SpectrumPtr& spectrum() const { return spectrum_; }
  SampledSpectrum sample(const SampledWavelengths& lambda) const {
    return memo_sampled(key_, lambda, [&] { return spectrum_->sample(lambda); });
  }

 private:
  SpectrumPtr spectrum_;
  uint64_t key_;
};

}  // namespace ochre
