#pragma once
// SampledSpectrum: a quantity at the 4 hero wavelengths of one path (one lane each).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace ochre {

inline constexpr int kSpectrumSamples = 4;

class SampledSpectrum {
 public:
  constexpr SampledSpectrum() = default;
  constexpr explicit SampledSpectrum(float c) : v_{c, c, c, c} {}
  constexpr SampledSpectrum(float a, float b, float c, float d) : v_{a, b, c, d} {}

  constexpr float& operator[](int i) { return v_[i]; }
  constexpr float operator[](int i) const { return v_[i]; }

#define OCHRE_SPECTRUM_OP(op)                                                                 \
  constexpr SampledSpectrum& operator op##=(const SampledSpectrum& o) {                       \
    for (int i = 0; i < kSpectrumSamples; ++i) v_[i] op## = o.v_[i];                          \
    return *this;                                                                             \
  }                                                                                           \
  constexpr SampledSpectrum& operator op##=(float s) {                                        \
    for (int i = 0; i < kSpectrumSamples; ++i) v_[i] op## = s;                                \
    return *this;                                                                             \
  }                                                                                           \
  friend constexpr SampledSpectrum operator op(SampledSpectrum a, const SampledSpectrum& b) { \
    return a op## = b;                                                                        \
  }                                                                                           \
  friend constexpr SampledSpectrum operator op(SampledSpectrum a, float s) {                  \
    return a op## = s;                                                                        \
  }
  OCHRE_SPECTRUM_OP(+)
  OCHRE_SPECTRUM_OP(-)
  OCHRE_SPECTRUM_OP(*)
#undef OCHRE_SPECTRUM_OP

  friend constexpr SampledSpectrum operator*(float s, SampledSpectrum a) {
    return a *= s;
  }
  friend constexpr SampledSpectrum operator+(float s, SampledSpectrum a) {
    return a += s;
  }
  friend constexpr SampledSpectrum operator-(float s, const SampledSpectrum& a) {
    return SampledSpectrum(s) - a;
  }

  // Division that maps x / 0 to 0 (a zero pdf means "no contribution", never Inf).
  friend constexpr SampledSpectrum safe_div(const SampledSpectrum& a, const SampledSpectrum& b) {
    SampledSpectrum r;
    for (int i = 0; i < kSpectrumSamples; ++i) r.v_[i] = b.v_[i] != 0.0f ? a.v_[i] / b.v_[i] : 0.0f;
    return r;
  }
  constexpr SampledSpectrum& operator/=(float s) {
    const float inv = 1.0f / s;
    return *this *= inv;
  }
  friend constexpr SampledSpectrum operator/(SampledSpectrum a, float s) {
    return a /= s;
  }
  friend constexpr SampledSpectrum operator/(SampledSpectrum a, const SampledSpectrum& b) {
    for (int i = 0; i < kSpectrumSamples; ++i) a.v_[i] /= b.v_[i];
    return a;
  }
  friend constexpr bool operator==(const SampledSpectrum&, const SampledSpectrum&) = default;

  constexpr bool is_black() const {
    for (float x : v_)
      if (x != 0.0f) return false;
    return true;
  }
  bool is_finite() const {
    for (float x : v_)
      if (!std::isfinite(x)) return false;
    return true;
  }
  constexpr float max_value() const {
    return std::max(std::max(v_[0], v_[1]), std::max(v_[2], v_[3]));
  }
  constexpr float min_value() const {
    return std::min(std::min(v_[0], v_[1]), std::min(v_[2], v_[3]));
  }
  constexpr float average() const {
    return (v_[0] + v_[1] + v_[2] + v_[3]) * 0.25f;
  }

 private:
  std::array<float, kSpectrumSamples> v_{};
};

inline SampledSpectrum exp(const SampledSpectrum& s) {
  return {std::exp(s[0]), std::exp(s[1]), std::exp(s[2]), std::exp(s[3])};
}
inline SampledSpectrum clamp_zero(const SampledSpectrum& s) {
  return {std::max(s[0], 0.0f), std::max(s[1], 0.0f), std::max(s[2], 0.0f), std::max(s[3], 0.0f)};
}

}  // namespace ochre
