#pragma once
// Bit-for-bit comparison of two EXR files' pixels (every channel, float bits compared with memcmp so that
// -0 and +0 or two NaNs are told apart), for the split, merge and checkpoint tests.

#include <gtest/gtest.h>

#include <filesystem>

namespace ochre::test {

// Success when both files have the same channels, size and pixel bits; the failure names the first
// channel and pixel that differ.
::testing::AssertionResult same_exr_pixels(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace ochre::test
