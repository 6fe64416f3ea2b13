#pragma once
// ProductSpectrum: the wavelength-wise product of two spectra (e.g. a reflectance under an
// illuminant).
//
//   ProductSpectrum(SpectrumPtr a, SpectrumPtr b)   (throws std::invalid_argument for null inputs)

#include <stdexcept>
#include <utility>

#include "spectra/spectrum.h"

namespace ochre {

class ProductSpectrum final : public Spectrum {
 public:
  ProductSpectrum(SpectrumPtr a, SpectrumPtr b) : a_(std::move(a)), b_(std::move(b)) {
    if (!a_ || !b_) throw std::invalid_argument("ProductSpectrum: null factor spectrum");
  }

  float eval(float lambda_nm) const override { return a_->eval(lambda_nm) * b_->eval(lambda_nm); }
  SampledSpectrum sample(const SampledWavelengths& lambda) const override {
    return a_->sample(lambda) * b_->sample(lambda);
  }
  // Product of the two maxima: an upper bound for non-negative spectra (the common case).
  float max_value() const override { return a_->max_value() * b_->max_value(); }
  bool is_constant() const override { return a_->is_constant() && b_->is_constant(); }

 private:
  SpectrumPtr a_, b_;
};

}  // namespace ochre
