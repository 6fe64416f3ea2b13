#pragma once
// WavelengthMemo: a per-thread memo of spectra sampled at a path's wavelengths.
//
// A path keeps its wavelengths from the camera to its last vertex, and many spectra it samples do not
// depend on the shading point: a material's tabulated reflectance, a uniform emitter, the D65 white of an
// environment map's texels. Each such spectrum takes a key from new_wavelength_memo_key() (a number never
// handed out twice in the process, so a key cannot outlive its spectrum as a reused address could) and asks
// memo_sampled(key, lambda, compute): the value is computed on the first request for these wavelengths and
// returned from the thread's table after that. Each call site (each Compute type) has its own direct-mapped
// table of 64 entries; a collision only costs a recomputation. The value is the same function of the same
// arguments, so images do not change.

#include <array>
#include <atomic>
#include <cstdint>

#include "spectra/sampled_wavelengths.h"

namespace ochre {

// A key for memo_sampled(); never 0 (the mark of an empty entry), never repeated.
inline uint64_t new_wavelength_memo_key() {
  static std::atomic<uint64_t> counter{0};
  return counter.fetch_add(1, std::memory_order_relaxed) + 1;
}

// compute() is called as compute() -> SampledSpectrum when the thread holds no value for (key, lambda).
template <class Compute>
SampledSpectrum memo_sampled(uint64_t key, const SampledWavelengths& lambda, Compute&& compute) {
  struct Entry {
    uint64_t key = 0;
    SampledSpectrum lambda, value;
  };
  thread_local std::array<Entry, 64> table;
  Entry& e = table[key % table.size()];
  if (e.key != key || !(e.lambda == lambda.lambda())) {
    const SampledSpectrum value = compute();
    e = {key, lambda.lambda(), value};
  }
  return e.value;
}

}  // namespace ochre
