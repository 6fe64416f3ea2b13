#pragma once
// ScaledSpectrum: another spectrum times a constant factor (e.g. an illuminant at a given
// luminance).
//
//   ScaledSpectrum(SpectrumPtr base, float scale)   (throws std::invalid_argument for a null base)

#include <stdexcept>
#include <utility>

#include "spectra/spectrum.h"

namespace ochre {

class ScaledSpectrum final : public Spectrum {
 public:
  ScaledSpectrum(SpectrumPtr base, float scale) : base_(std::move(base)), scale_(scale) {
    if (!base_) throw std::invalid_argument("ScaledSpectrum: null base spectrum");
  }

  float eval(float lambda_nm) const override { return scale_ * base_->eval(lambda_nm); }
  SampledSpectrum sample(const SampledWavelengths& lambda) const override {
    return scale_ * base_->sample(lambda);
  }
  // With a negative scale (unusual) the values of a non-negative base are <= 0: bound them by 0.
  float max_value() const override { return scale_ >= 0.0f ? scale_ * base_->max_value() : 0.0f; }
  bool is_constant() const override { return scale_ == 0.0f || base_->is_constant(); }

  const SpectrumPtr& base() const { return base_; }
  float scale() const { return scale_; }

 private:
  SpectrumPtr base_;
  float scale_;
};

}  // namespace ochre
