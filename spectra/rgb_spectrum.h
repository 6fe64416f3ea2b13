#pragma once
// Spectra from RGB triples in linear Rec.709 / sRGB (Jakob & Hanika 2019 upsampling, as in
// pbrt-v4). Convert colours from other working spaces to linear Rec.709 first.
//
//   RGBAlbedoSpectrum(RGB)       reflectance: components clamped to [0, 1], values in [0, 1];
//                                its colour under D65 is rgb.
//   RGBUnboundedSpectrum(RGB)    any non-negative rgb (negative components are clamped to 0):
//                                scale = 2 max(rgb), spectrum = scale * sigmoid(rgb / scale)
//   RGBIlluminantSpectrum(RGB)   emission: unbounded spectrum times D65 at luminance 1 (d65());
//                                RGB (1,1,1) gives exactly d65(), whose colour is RGB (1,1,1).

#include "spectra/color_types.h"
#include "spectra/rgb_sigmoid_polynomial.h"
#include "spectra/spectrum.h"

namespace ochre {

// pbrt-v4's decomposition of an unbounded colour: rgb = scale * (the bounded colour rgb / scale) with
// scale = 2 max(rgb), which puts the largest component at 0.5, the middle of the sigmoid's range, where
// the fit is smoothest (a grey rgb gives the constant 0.5 exactly). Negative and NaN components count as
// 0, +inf as the largest float; the scale is at most the largest float (every value stays finite).
struct UnboundedRGB {
  float scale = 0.0f;
  RGBSigmoidPolynomial poly;
};
UnboundedRGB decompose_unbounded(RGB rgb);

class RGBAlbedoSpectrum final : public Spectrum {
 public:
  explicit RGBAlbedoSpectrum(RGB rgb);

  float eval(float lambda_nm) const override { return poly_.eval(lambda_nm); }
  float max_value() const override { return poly_.max_value(); }
  bool is_constant() const override { return poly_.c0 == 0.0f && poly_.c1 == 0.0f; }
  const RGBSigmoidPolynomial& polynomial() const { return poly_; }

 private:
  RGBSigmoidPolynomial poly_;
};

class RGBUnboundedSpectrum final : public Spectrum {
 public:
  explicit RGBUnboundedSpectrum(RGB rgb);

  float eval(float lambda_nm) const override { return scale_ * poly_.eval(lambda_nm); }
  float max_value() const override { return scale_ * poly_.max_value(); }
  bool is_constant() const override { return scale_ == 0.0f || (poly_.c0 == 0.0f && poly_.c1 == 0.0f); }

 private:
  float scale_;
  RGBSigmoidPolynomial poly_;
};

class RGBIlluminantSpectrum final : public Spectrum {
 public:
  explicit RGBIlluminantSpectrum(RGB rgb);

  float eval(float lambda_nm) const override {
    return scale_ * poly_.eval(lambda_nm) * illuminant_->eval(lambda_nm);
  }
  SampledSpectrum sample(const SampledWavelengths& lambda) const override;
  float max_value() const override { return scale_ * poly_.max_value() * illuminant_->max_value(); }

 private:
  float scale_;
  RGBSigmoidPolynomial poly_;
  SpectrumPtr illuminant_;
};

}  // namespace ochre
