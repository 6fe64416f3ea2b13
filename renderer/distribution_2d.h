#pragma once
// Piecewise-constant 2D distribution over [0,1)^2 on a width x height grid of cells (pbrt-v4's
// PiecewiseConstant2D, section A.5.6): a marginal Distribution1D over rows picks a row in proportion
// to the row's total weight, then that row's conditional Distribution1D picks a column. Inside the
// chosen cell the point is uniform, so the density is constant per cell:
//   pdf(u, v) = P(row) * P(column | row) * width * height.
// Row 0 is v in [0, 1/height) (the top row of an image), column 0 is u in [0, 1/width).
//
// Layout: an environment map's sampling is a random access into megabytes of CDFs, so the conditional
// CDFs live in one flat array whose entries pair each CDF value with the guide-table entry (Chen & Asau
// 1974) of the same index: a row search reads the guide entry of u's bucket and the one or two CDF values
// it points to, which for a row of similar weights sit beside it (typically one cache line), and a pdf
// query reads one float of the per-cell table.

#include <cstdint>
#include <vector>

#include "materials/vec3.h"
#include "renderer/distribution_1d.h"

namespace ochre {

class Distribution2D {
 public:
  struct Sample {
    Vec2 uv;         // the point, in [0,1)^2
    int column = 0;  // its cell
    int row = 0;
    float pdf = 0.0f;  // density with respect to du dv
  };

  Distribution2D() = default;
  // weights: width * height non-negative values, row-major, row 0 first. All zero -> empty().
  Distribution2D(const std::vector<double>& weights, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return marginal_.empty(); }

  // Maps two uniform numbers in [0,1) to a point distributed in proportion to the weights.
  Sample sample(const Vec2& u) const;
  // Density of sample() at a cell (with respect to du dv), and at a point (its cell's density).
  float pdf(int column, int row) const;
  float pdf(const Vec2& uv) const;

 private:
  int width_ = 0;
  int height_ = 0;
  // Column of row `row` for u, and u rescaled inside it (the conditional distribution).
  int sample_column(int row, float u, float* u_in_column) const;

  Distribution1D marginal_;  // over rows
  struct RowEntry {
    float cdf = 0.0f;    // normalised CDF before column i (entry width is exactly 1)
    uint32_t guide = 0;  // the first index j >= 1 with cdf[j] > i / width
  };
  std::vector<RowEntry> rows_;   // per row: width + 1 entries
  std::vector<float> cell_pdf_;  // pdf(column, row), row-major: one memory access per query
};

}  // namespace ochre
