#include "renderer/film/render_split.h"

#include <fmt/format.h>

#include <charconv>
#include <vector>

namespace ochre {

namespace {

// A whole decimal integer in [0, max]; nullopt for anything else (sign, spaces, overflow).
std::optional<uint64_t> parse_count(std::string_view text, uint64_t max) {
  uint64_t value = 0;
  if (text.empty() || text.front() == '+' || text.front() == '-') return std::nullopt;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value > max) return std::nullopt;
  return value;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> fields;
  for (size_t start = 0;;) {
    const size_t end = text.find(separator, start);
    fields.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return fields;
    start = end + 1;
  }
}

constexpr uint64_t kMaxCoordinate = 1u << 30;

}  // namespace

std::optional<SampleRange> parse_sample_range(std::string_view text) {
  const std::vector<std::string_view> fields = split(text, ':');
  if (fields.size() != 2) return std::nullopt;
  const auto begin = parse_count(fields[0], kMaxSampleEnd), end = parse_count(fields[1], kMaxSampleEnd);
  if (!begin || !end || *begin >= *end) return std::nullopt;
  return SampleRange{static_cast<uint32_t>(*begin), static_cast<uint32_t>(*end)};
}

std::optional<PixelRect> parse_pixel_rect(std::string_view text) {
  const std::vector<std::string_view> fields = split(text, ',');
  if (fields.size() != 4) return std::nullopt;
  int values[4];
  for (int i = 0; i < 4; ++i) {
    const auto value = parse_count(fields[i], kMaxCoordinate);
    if (!value) return std::nullopt;
    values[i] = static_cast<int>(*value);
  }
  const PixelRect rect{values[0], values[1], values[2], values[3]};
  if (rect.empty()) return std::nullopt;
  return rect;
}

std::optional<std::pair<uint32_t, uint32_t>> parse_part(std::string_view text) {
  const std::vector<std::string_view> fields = split(text, '/');
  if (fields.size() != 2) return std::nullopt;
  const auto index = parse_count(fields[0], kMaxSampleEnd), count = parse_count(fields[1], kMaxSampleEnd);
  if (!index || !count || *index >= *count) return std::nullopt;
  return std::pair{static_cast<uint32_t>(*index), static_cast<uint32_t>(*count)};
}

std::optional<GridTile> parse_grid_tile(std::string_view text) {
  const std::vector<std::string_view> fields = split(text, '/');
  if (fields.size() != 2) return std::nullopt;
  const std::vector<std::string_view> grid = split(fields[1], 'x');
  if (grid.size() != 2) return std::nullopt;
  const auto index = parse_count(fields[0], kMaxCoordinate);
  const auto columns = parse_count(grid[0], kMaxCoordinate), rows = parse_count(grid[1], kMaxCoordinate);
  if (!index || !columns || !rows || *columns < 1 || *rows < 1 || *index >= *columns * *rows)
    return std::nullopt;
  return GridTile{static_cast<uint32_t>(*index), static_cast<uint32_t>(*columns),
                  static_cast<uint32_t>(*rows)};
}

PixelRect tile_rect(const GridTile& tile, int width, int height) {
  const auto bound = [](uint64_t i, uint64_t size, uint64_t count) {
    return static_cast<int>(i * size / count);
  };
  const uint32_t column = tile.index % tile.columns, row = tile.index / tile.columns;
  return {bound(column, width, tile.columns), bound(row, height, tile.rows),
          bound(column + 1, width, tile.columns), bound(row + 1, height, tile.rows)};
}

std::string format_sample_range(const SampleRange& range) {
  return fmt::format("{}:{}", range.begin, range.end);
}

std::string format_pixel_rect(const PixelRect& rect) {
  return fmt::format("{},{},{},{}", rect.x0, rect.y0, rect.x1, rect.y1);
}

SampleRange part_of_samples(uint32_t index, uint32_t count, uint32_t spp) {
  const auto bound = [&](uint64_t i) { return static_cast<uint32_t>(i * spp / count); };
  return {bound(index), bound(static_cast<uint64_t>(index) + 1)};
}

}  // namespace ochre
