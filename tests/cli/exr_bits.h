#pragma once
// Comparing rendered images: two EXR files' pixels bit for bit (every channel, float bits compared with
// memcmp so that -0 and +0 or two NaNs are told apart), for the split, merge and checkpoint tests; two
// images' R, G, B values, for the determinism and frame-sequence tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/image/exr_writer.h"

namespace ochre::test {

// Success when both files have the same channels, size and pixel bits; the failure names the first
// channel and pixel that differ.
::testing::AssertionResult same_exr_pixels(const std::filesystem::path& a, const std::filesystem::path& b);

// True when two images read back have equal R, G and B values (compared as floats), false when a value
// differs or an image lacks one of them.
bool same_rgb_values(const ExrImage& a, const ExrImage& b);

// Writes a copy of the EXR `from` to `to` whose string attribute `name` holds `value` (a forged header, for
// the tests of bad parts and checkpoints). The value must have the old value's length: the header's size,
// and with it the offset table after it, stays the same. A failure names the attribute.
::testing::AssertionResult copy_with_string_attribute(const std::filesystem::path& from,
                                                      const std::filesystem::path& to,
                                                      const std::string& name, const std::string& value);

// The channel `name` of an image read back; std::runtime_error naming it when the image lacks it (a test
// failure, not a crash).
const std::vector<float>& exr_channel(const ExrImage& image, const std::string& name);

// The mean of a channel's values.
double mean_of(const std::vector<float>& values);

}  // namespace ochre::test
