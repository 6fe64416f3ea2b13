// WavelengthMemo: a value is computed once per (key, wavelengths) and thread, recomputed when either
// changes, and keys that share a table slot never see each other's values.

#include "spectra/wavelength_memo.h"

#include <gtest/gtest.h>

#include <thread>

namespace ochre::wavelength_memo_test {
namespace {

SampledSpectrum counting(int& calls, float v) {
  ++calls;
  return SampledSpectrum(v);
}

TEST(WavelengthMemo, ComputesOncePerKeyAndWavelengths) {
  const uint64_t key = new_wavelength_memo_key();
  const SampledWavelengths a = SampledWavelengths::sample_visible(0.25f);
  const SampledWavelengths b = SampledWavelengths::sample_visible(0.75f);
  int calls = 0;
  auto get = [&](const SampledWavelengths& l, float v) {
    return memo_sampled(key, l, [&] { return counting(calls, v); });
  };
  EXPECT_EQ(get(a, 1.0f)[0], 1.0f);
  EXPECT_EQ(get(a, 2.0f)[0], 1.0f) << "same key and wavelengths: the memoized value";
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(get(b, 3.0f)[0], 3.0f) << "other wavelengths: computed again";
  EXPECT_EQ(calls, 2);
}

TEST(WavelengthMemo, KeysAreUniqueAndCollidingKeysKeepTheirOwnValues) {
  const SampledWavelengths l = SampledWavelengths::sample_visible(0.5f);
  const uint64_t first = new_wavelength_memo_key();
  uint64_t same_slot = 0;
  for (int i = 0; i < 64; ++i) same_slot = new_wavelength_memo_key();  // 64 later: the same slot
  ASSERT_NE(first, same_slot);
  ASSERT_EQ(first % 64, same_slot % 64);
  int calls = 0;
  auto get = [&](uint64_t key, float v) { return memo_sampled(key, l, [&] { return counting(calls, v); }); };
  EXPECT_EQ(get(first, 1.0f)[0], 1.0f);
  EXPECT_EQ(get(same_slot, 2.0f)[0], 2.0f);
  EXPECT_EQ(get(first, 1.0f)[0], 1.0f);
  EXPECT_EQ(calls, 3);
}

TEST(WavelengthMemo, EachThreadHasItsOwnTable) {
  const uint64_t key = new_wavelength_memo_key();
  const SampledWavelengths l = SampledWavelengths::sample_visible(0.1f);
  int calls = 0;
  auto get = [&] { return memo_sampled(key, l, [&] { return counting(calls, 5.0f); }); };
  get();
  std::thread other([&] { get(); });
  other.join();
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace ochre::wavelength_memo_test
