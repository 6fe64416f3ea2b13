#pragma once
// Spectrum: a function of wavelength (nm). Concrete kinds live in their own files:
// constant_spectrum.h, tabulated_spectrum.h, blackbody_spectrum.h, rgb_spectrum.h.

#include <memory>

#include "spectra/sampled_spectrum.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

class Spectrum {
 public:
  virtual ~Spectrum() = default;
  // Value at one wavelength in nm.
  virtual float eval(float lambda_nm) const = 0;
  // Values at the wavelengths of a path.
  virtual SampledSpectrum sample(const SampledWavelengths& lambda) const {
    SampledSpectrum s;
    for (int i = 0; i < kSpectrumSamples; ++i) s[i] = eval(lambda[i]);
    return s;
  }
  // Upper bound of the values over [360, 830] nm (used for light power and RR estimates).
  virtual float max_value() const = 0;
  // True when the spectrum is the same at every wavelength.
  virtual bool is_constant() const { return false; }
};

using SpectrumPtr = std::shared_ptr<const Spectrum>;

}  // namespace ochre
