#pragma once
// ConstantSpectrum: the same value at every wavelength.
//
//   ConstantSpectrum(float value); eval(lambda) == value; is_constant() == true

#include "spectra/spectrum.h"

namespace ochre {

class ConstantSpectrum final : public Spectrum {
 public:
  explicit ConstantSpectrum(float value) : value_(value) {}

  float eval(float) const override { return value_; }
  SampledSpectrum sample(const SampledWavelengths&) const override { return SampledSpectrum(value_); }
  float max_value() const override { return value_; }
  bool is_constant() const override { return true; }
  float value() const { return value_; }

 private:
  float value_;
};

}  // namespace ochre
