#pragma once
// The two ways a render is split between processes (docs/distributed.md): a range of sample indices
// [begin, end) of every pixel, and a rectangle of pixels [x0, x1) x [y0, y1) of the image. Their text
// forms are those of `ochre render --sample-range A:B --region x0,y0,x1,y1` and of the coverage recorded
// in partial-sum files.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ochre {

struct SampleRange {
  uint32_t begin = 0, end = 0;
  uint32_t size() const { return end - begin; }
  bool operator==(const SampleRange&) const = default;
};

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool contains(const PixelRect& other) const {
    return other.x0 >= x0 && other.y0 >= y0 && other.x1 <= x1 && other.y1 <= y1;
  }
  bool operator==(const PixelRect&) const = default;
};

// The largest end B of a sample range A:B: sample indices are 32-bit (SampleRange).
inline constexpr uint64_t kMaxSampleEnd = UINT32_MAX;

// "A:B" with 0 <= A < B <= kMaxSampleEnd in decimal; nullopt otherwise (the caller names the option or
// field).
std::optional<SampleRange> parse_sample_range(std::string_view text);
// "x0,y0,x1,y1" with 0 <= x0 < x1 and 0 <= y0 < y1 (integers); nullopt otherwise. Whether the rectangle
// fits the image is the caller's check.
std::optional<PixelRect> parse_pixel_rect(std::string_view text);
// "I/N" with 0 <= I < N: the I-th of N parts.
std::optional<std::pair<uint32_t, uint32_t>> parse_part(std::string_view text);

// Tile `index` (row by row from the top left, from 0) of a grid of `columns` x `rows` tiles.
struct GridTile {
  uint32_t index = 0, columns = 1, rows = 1;
};
// "I/CxR" with C, R >= 1 and 0 <= I < C R; nullopt otherwise.
std::optional<GridTile> parse_grid_tile(std::string_view text);
// The pixels of the tile in a width x height image: columns [c W / C, (c + 1) W / C), rows likewise; the
// tiles of a grid cover the image exactly once. Empty when the grid has more columns or rows than pixels.
PixelRect tile_rect(const GridTile& tile, int width, int height);

std::string format_sample_range(const SampleRange& range);  // "A:B"
std::string format_pixel_rect(const PixelRect& rect);       // "x0,y0,x1,y1"

// Part `index` of `count` equal parts of [0, spp): [index * spp / count, (index + 1) * spp / count).
SampleRange part_of_samples(uint32_t index, uint32_t count, uint32_t spp);

}  // namespace ochre
