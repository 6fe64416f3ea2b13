#include "cli/exr_bits.h"

#include <cstring>

#include "renderer/image/exr_reader.h"

namespace ochre::test {

::testing::AssertionResult same_exr_pixels(const std::filesystem::path& a, const std::filesystem::path& b) {
  const ExrImage x = read_exr(a), y = read_exr(b);
  if (x.width != y.width || x.height != y.height)
    return ::testing::AssertionFailure()
           << a << " is " << x.width << "x" << x.height << ", " << b << " is " << y.width << "x" << y.height;
  if (x.channels.size() != y.channels.size())
    return ::testing::AssertionFailure()
           << a << " has " << x.channels.size() << " channels, " << b << " " << y.channels.size();
  for (size_t c = 0; c < x.channels.size(); ++c) {
    const auto& [name, values] = x.channels[c];
    if (name != y.channels[c].first)
      return ::testing::AssertionFailure()
             << "channel " << c << ": " << name << " vs " << y.channels[c].first;
    const std::vector<float>& other = y.channels[c].second;
    for (size_t i = 0; i < values.size(); ++i)
      if (std::memcmp(&values[i], &other[i], sizeof(float)) != 0)
        return ::testing::AssertionFailure()
               << "channel " << name << ", pixel " << i << ": " << values[i] << " vs " << other[i];
  }
  return ::testing::AssertionSuccess() << x.channels.size() << " channels identical";
}

bool same_rgb_values(const ExrImage& a, const ExrImage& b) {
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float>*x = a.find_channel(c), *y = b.find_channel(c);
    if (!x || !y || *x != *y) return false;
  }
  return true;
}

}  // namespace ochre::test
