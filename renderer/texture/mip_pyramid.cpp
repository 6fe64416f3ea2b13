#include "renderer/texture/mip_pyramid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "renderer/image/image_library.h"
#include "renderer/texture/periodic_texture_coordinate.h"

namespace ochre {

namespace {

// Periodic wrap of a texel index (any sign) into [0, n).
int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// The texel of a row or column of `size` at floor coordinate f, wrapped: lookups give f in [-1, size - 1]
// (their coordinates are first made periodic), which skips the remainders; a very large |f| would
// overflow int, so anything else is wrapped in float first (the lookup is periodic anyway).
int texel_index(float f, int size) {
  if (f >= -1.0f && f < static_cast<float>(size)) {
    const int i = static_cast<int>(f);
    return i < 0 ? i + size : i;
  }
  return wrap(static_cast<int>(std::fmod(f, static_cast<float>(size))), size);
}

}  // namespace

MipPyramid::MipPyramid(std::vector<Level> levels, int channels)
    : levels_(std::move(levels)), channels_(channels) {
  if (levels_.empty() || channels < 1 || channels > 4)
    throw std::invalid_argument("MipPyramid: needs at least one level and 1..4 channels");
  for (const Level& l : levels_)
    if (l.width < 1 || l.height < 1 ||
        l.texels.size() != static_cast<std::size_t>(l.width) * l.height * static_cast<std::size_t>(channels))
      throw std::invalid_argument("MipPyramid: a level's texel count does not match its size");
  level0_size_ = static_cast<float>(std::max(levels_[0].width, levels_[0].height));
}

std::size_t MipPyramid::file_bytes(const std::filesystem::path& file) {
  ImageHeader header;
  try {
    header = image_library().read_header(file.string());
  } catch (const std::runtime_error&) {
    return 0;
  }
  std::size_t bytes = 0;
  for (const ImageLevelSize& level : header.levels) {
    bytes += static_cast<std::size_t>(level.width) * level.height * level.channels * sizeof(float);
  }
  return bytes;
}

MipPyramid MipPyramid::load(const std::filesystem::path& file) {
  const ImageLibrary& library = image_library();
  ImageHeader header;
  try {
    header = library.read_header(file.string());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("cannot read texture {}: {}", file.string(), e.what()));
  }
  const int channels = header.channels;
  std::vector<Level> levels;
  for (int m = 0; m < static_cast<int>(header.levels.size()); ++m) {
    const ImageLevelSize& size = header.levels[static_cast<std::size_t>(m)];
    if (size.channels != channels)
      throw std::runtime_error(fmt::format("texture {}: MIP level {} has {} channels, level 0 {}",
                                           file.string(), m, size.channels, channels));
    Level level;
    level.width = size.width;
    level.height = size.height;
    try {
      level.texels = library.read_float(file.string(), m, {size.width, size.height, channels});
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(
          fmt::format("cannot read MIP level {} of texture {}: {}", m, file.string(), e.what()));
    }
    levels.push_back(std::move(level));
  }
  try {
    return MipPyramid(std::move(levels), channels);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("texture {}: {}", file.string(), e.what()));
  }
}

std::size_t MipPyramid::memory_bytes() const {
  std::size_t bytes = 0;
  for (const Level& l : levels_) bytes += l.texels.size() * sizeof(float);
  return bytes;
}

// Adds weight x the bilinear interpolation of the four texels around (s, t) to out.
void MipPyramid::bilinear(const Level& level, float s, float t, int first_channel, int n, float weight,
                          float* out) const {
  const float x = s * static_cast<float>(level.width) - 0.5f;
  const float y = t * static_cast<float>(level.height) - 0.5f;
  const float x0f = std::floor(x), y0f = std::floor(y);
  const float fx = x - x0f, fy = y - y0f;
  const int x0 = texel_index(x0f, level.width), y0 = texel_index(y0f, level.height);
  const int x1 = x0 + 1 == level.width ? 0 : x0 + 1;
  const int y1 = y0 + 1 == level.height ? 0 : y0 + 1;
  const std::size_t stride = static_cast<std::size_t>(channels_);
  const float* row0 = level.texels.data() + static_cast<std::size_t>(y0) * level.width * stride;
  const float* row1 = level.texels.data() + static_cast<std::size_t>(y1) * level.width * stride;
  const float w00 = (1.0f - fx) * (1.0f - fy) * weight, w10 = fx * (1.0f - fy) * weight;
  const float w01 = (1.0f - fx) * fy * weight, w11 = fx * fy * weight;
  const float* a = row0 + x0 * stride + first_channel;
  const float* b = row0 + x1 * stride + first_channel;
  const float* c = row1 + x0 * stride + first_channel;
  const float* d = row1 + x1 * stride + first_channel;
  for (int k = 0; k < n; ++k) out[k] += w00 * a[k] + w10 * b[k] + w01 * c[k] + w11 * d[k];
}

void MipPyramid::lookup(float s, float t, float footprint, int first_channel, int n, float* out) const {
  std::fill(out, out + n, 0.0f);
  if (!std::isfinite(s) || !std::isfinite(t)) return;
  s = periodic_texture_coordinate(s);
  t = periodic_texture_coordinate(t);
  const float texels = std::fabs(footprint) * level0_size_;
  const float lod = texels > 1.0f ? std::log2(texels) : 0.0f;  // NaN footprint -> level 0
  const int last = level_count() - 1;
  if (!(lod < static_cast<float>(last))) {
    bilinear(levels_[static_cast<std::size_t>(last)], s, t, first_channel, n, 1.0f, out);
    return;
  }
  const int l0 = static_cast<int>(lod);
  const float blend = lod - static_cast<float>(l0);
  bilinear(levels_[static_cast<std::size_t>(l0)], s, t, first_channel, n, 1.0f - blend, out);
  if (blend > 0.0f) bilinear(levels_[static_cast<std::size_t>(l0 + 1)], s, t, first_channel, n, blend, out);
}

}  // namespace ochre
