#include "tools/regress/pixel_grid.h"

#include <algorithm>
#include <cmath>

namespace ochre {

namespace {

float combine(float acc, float v, BlockReduce reduce) {
  switch (reduce) {
    case BlockReduce::kExtreme:
      if (std::isnan(acc)) return acc;
      return std::isnan(v) || std::fabs(v) > std::fabs(acc) ? v : acc;
    case BlockReduce::kMax:
      return std::isnan(acc) || v > acc ? v : acc;
    case BlockReduce::kMean:
    case BlockReduce::kSum:
      return acc + v;
  }
  return acc;
}

}  // namespace

PixelGrid make_pixel_grid(int width, int height, int step) {
  PixelGrid grid;
  grid.width = width;
  grid.height = height;
  grid.step = step;
  grid.columns = (width + step - 1) / step;
  grid.rows = (height + step - 1) / step;
  return grid;
}

PixelGrid choose_pixel_grid(int width, int height, size_t values_per_cell, size_t max_values) {
  const size_t per_cell = values_per_cell > 0 ? values_per_cell : 1;
  for (int step = 1;; ++step) {
    const PixelGrid grid = make_pixel_grid(width, height, step);
    if (grid.cells() * per_cell <= max_values || (grid.columns <= 1 && grid.rows <= 1)) return grid;
  }
}

std::vector<float> reduce_to_grid(const std::vector<float>& values, int components, const PixelGrid& grid,
                                  BlockReduce reduce) {
  const size_t c = static_cast<size_t>(components);
  std::vector<float> cells(grid.cells() * c, 0.0f);
  std::vector<bool> started(grid.cells(), false);
  std::vector<int> counts(grid.cells(), 0);
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const size_t cell = static_cast<size_t>(y / grid.step) * grid.columns + x / grid.step;
      const size_t pixel = static_cast<size_t>(y) * grid.width + x;
      for (size_t k = 0; k < c; ++k) {
        const float v = values[pixel * c + k];
        cells[cell * c + k] = started[cell] ? combine(cells[cell * c + k], v, reduce) : v;
      }
      started[cell] = true;
      ++counts[cell];
    }
  if (reduce == BlockReduce::kMean)
    for (size_t cell = 0; cell < grid.cells(); ++cell)
      for (size_t k = 0; k < c; ++k) cells[cell * c + k] /= static_cast<float>(counts[cell]);
  return cells;
}

}  // namespace ochre
