#pragma once
// exp and log in single precision as straight-line arithmetic: no branch, no table, no library call, so a
// loop over a spectrum's eight wavelengths compiles to vector instructions (the library's are one call per
// lane: they were most of the Lambert-sphere lobe's cost, three exp per wavelength per evaluation and four
// pow per wavelength per shading point). Both are within 2 units in the last place of the correctly
// rounded value over their whole range (tests/materials/numerics/branchless_math_test.cpp). The loops
// that use them vectorize only without -ftrapping-math (materials/CMakeLists.txt).

#include <bit>
#include <cstdint>

namespace ochre {

// exp(x) = 2^n exp(r) with n = round(x / ln 2) and |r| <= ln 2 / 2; r = x - n ln 2 with ln 2 split in
// two parts (the first has 16 significant bits, so n times it is exact: Cody and Waite's reduction);
// exp(r) by its Taylor polynomial to degree 7 (truncation error 0.3466^8 / 8! = 5e-9, below half a unit
// in the last place); 2^n built in the exponent field. x is clamped to [-87, 88] first, so the result is
// always a finite normal float (exp(-87) = 1.6e-38 where the true value is smaller); NaN gives exp(-87):
// callers pass finite arguments.
inline float branchless_exp(float x) {
  constexpr float kLog2e = 1.44269504088896341f;
  constexpr float kLn2High = 0.693145751953125f;  // 0xb172 / 2^16
  constexpr float kLn2Low = 1.42860682030941723e-6f;
  constexpr float kRoundingShift = 12582912.0f;  // 1.5 * 2^23: adding it rounds to an integer
  x = x < 88.0f ? x : 88.0f;  // value comparisons (not std::min's references) if-convert into vector code
  x = x > -87.0f ? x : -87.0f;
  const float n = (x * kLog2e + kRoundingShift) - kRoundingShift;
  const float r = (x - n * kLn2High) - n * kLn2Low;
  float p = 1.0f / 5040.0f;
  p = p * r + 1.0f / 720.0f;
  p = p * r + 1.0f / 120.0f;
  p = p * r + 1.0f / 24.0f;
  p = p * r + 1.0f / 6.0f;
  p = p * r + 0.5f;
  p = p * r + 1.0f;
  p = p * r + 1.0f;
  const float two_to_n = std::bit_cast<float>((static_cast<int32_t>(n) + 127) << 23);
  return p * two_to_n;
}

// log(x) for a positive normal float x (x below the smallest normal, 1.18e-38, counts as that value;
// callers pass positive arguments). x = m 2^e with m in [sqrt(1/2), sqrt(2)) read from the bits; log m =
// 2 atanh(z) with z = (m - 1) / (m + 1), |z| <= 0.1716, by its series to z^9 (truncation 2 z^11 / 11 =
// 7e-10 relative); e ln 2 added in two parts as in branchless_exp.
inline float branchless_log(float x) {
  constexpr float kSmallestNormal = 1.17549435e-38f;
  constexpr float kLn2High = 0.693145751953125f;
  constexpr float kLn2Low = 1.42860682030941723e-6f;
  x = x > kSmallestNormal ? x : kSmallestNormal;
  const int32_t bits = std::bit_cast<int32_t>(x);
  // m in [1, 2) from the mantissa bits; halved (and e raised) above sqrt(2).
  float m = std::bit_cast<float>((bits & 0x007fffff) | 0x3f800000);
  float e = static_cast<float>((bits >> 23) - 127);
  const bool above = m > 1.41421356f;
  m = above ? m * 0.5f : m;
  e = above ? e + 1.0f : e;
  const float z = (m - 1.0f) / (m + 1.0f), z2 = z * z, two_z = 2.0f * z;
  // 2z + 2z (z^2/3 + z^4/5 + ...): the leading term alone carries z's rounding, the rest is a small
  // correction.
  float q = 1.0f / 9.0f;
  q = q * z2 + 1.0f / 7.0f;
  q = q * z2 + 1.0f / 5.0f;
  q = q * z2 + 1.0f / 3.0f;
  const float log_m = two_z + two_z * (z2 * q);
  return e * kLn2High + (log_m + e * kLn2Low);
}

}  // namespace ochre
