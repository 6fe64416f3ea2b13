#include "cli/exr_bits.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

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

::testing::AssertionResult copy_with_string_attribute(const std::filesystem::path& from,
                                                      const std::filesystem::path& to,
                                                      const std::string& name, const std::string& value) {
  std::ifstream in(from, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  // name, NUL, the type "string", NUL, the value's size (4 bytes, little-endian), the value.
  const std::string key = name + std::string(1, '\0') + "string" + std::string(1, '\0');
  const size_t at = bytes.find(key);
  if (at == std::string::npos)
    return ::testing::AssertionFailure() << from << " has no string attribute " << name;
  const size_t size_at = at + key.size();
  uint32_t size = 0;
  for (int i = 3; i >= 0; --i) size = size << 8 | static_cast<uint8_t>(bytes[size_at + i]);
  if (size != value.size())
    return ::testing::AssertionFailure()
           << name << ": the old value has " << size << " bytes, the new " << value.size();
  bytes.replace(size_at + 4, size, value);
  std::ofstream(to, std::ios::binary) << bytes;
  return ::testing::AssertionSuccess();
}

const std::vector<float>& exr_channel(const ExrImage& image, const std::string& name) {
  const std::vector<float>* c = image.find_channel(name);
  if (!c) throw std::runtime_error("the image has no channel " + name);
  return *c;
}

double mean_of(const std::vector<float>& values) {
  double sum = 0.0;
  for (float v : values) sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

}  // namespace ochre::test
