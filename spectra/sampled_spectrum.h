#pragma once
// SampledSpectrum: a quantity at the hero wavelengths of one path (one lane each).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

namespace ochre {

// Wavelengths per path. Eight rather than four: the geometry of a path (its rays, shading frames, light
// choices) is shared by all lanes, so four more wavelengths cost 6-30 % more time per sample but cut colour
// noise (relMSE x time 11 % lower on the Cornell box benchmark, 25 % on the textured rock, 1.2-4x on
// spectrally sharp polarized scenes; docs/performance.md, lever g). Eight floats are one AVX register, two
// SSE ones; 16 lanes measured slower per unit of error.
inline constexpr int kSpectrumSamples = 8;

class SampledSpectrum {
 public:
  constexpr SampledSpectrum() = default;
  constexpr explicit SampledSpectrum(float c) { v_.fill(c); }

  constexpr float& operator[](int i) { return v_[i]; }
  constexpr float operator[](int i) const { return v_[i]; }
  // The lanes as one array, for functions of spans of floats.
  constexpr std::span<const float, kSpectrumSamples> lanes() const { return v_; }
  constexpr std::span<float, kSpectrumSamples> lanes() { return v_; }

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
    float m = v_[0];
    for (float x : v_) m = std::max(m, x);
    return m;
  }
  constexpr float min_value() const {
    float m = v_[0];
    for (float x : v_) m = std::min(m, x);
    return m;
  }
  constexpr float average() const {
    float sum = 0.0f;
    for (float x : v_) sum += x;
    return sum / kSpectrumSamples;
  }

 private:
  std::array<float, kSpectrumSamples> v_{};
};

inline SampledSpectrum exp(SampledSpectrum s) {
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = std::exp(s[i]);
  return s;
}
inline SampledSpectrum clamp_zero(SampledSpectrum s) {
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = std::max(s[i], 0.0f);
  return s;
}

}  // namespace ochre
