#pragma once
// Piecewise-constant 2D distribution over [0,1)^2 on a width x height grid of cells (the density of
// pbrt-v4's PiecewiseConstant2D, section A.5.6): the probability of a cell is its weight over the total and
// the point is uniform inside the cell, so the density is constant per cell:
//   pdf(u, v) = P(cell) * width * height.
// Row 0 is v in [0, 1/height) (the top row of an image), column 0 is u in [0, 1/width).
//
// Layout (two levels, for the cache): an environment map's sampling is a random access into megabytes of
// tables, so the cells are grouped in blocks of kBlock x kBlock (the last block row and column padded with
// zero-weight cells) and the sample is drawn by CDF inversions at two levels:
//   1. a coarse 2D distribution over blocks: a marginal Distribution1D over block rows, then the block row's
//      conditional CDF over block columns (one flat array pairing each CDF value with its guide-table entry,
//      Chen & Asau 1974, searched as Distribution1D searches). 1024 x 512 cells give 256 x 128 blocks: 2 KB
//      of marginal and 260 KB of conditionals, of which a sample reads one or two lines;
//   2. inside the block, one 64-byte record of its kBlock^2 cell densities: the row among kBlock by the row
//      sums, then the column among kBlock in that row (2 MB of records for 1024 x 512 cells).
// Each level is an inversion of a CDF, with u rescaled inside the chosen interval and passed down, so the map
// from u to the point is monotone in u.x for a fixed u.y and keeps the stratification of (0,2)-sequences
// (no alias table). A pdf query reads one float of one block record, which holds the final density
// P(block) * P(cell | block) * width * height; P(block) is computed from the coarse CDFs as rounded (the
// conditional's float CDF), i.e. it is the probability sample() really gives the block, so pdf() is the
// density sample() really has.
//
// Cells have a "key": their position in block-major order (block index * kBlock^2 + the row-major position
// inside the block), for callers that keep per-cell data in the same order so that a cell's data sits next
// to its block's neighbours.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "materials/core/vec3.h"
#include "renderer/sampling/distribution_1d.h"
#include "spectra/non_finite.h"

namespace ochre {

class Distribution2D {
 public:
  static constexpr int kBlock = 4;  // cells per block side: 16 floats = one 64-byte cache line
  static constexpr int kCellsPerBlock = kBlock * kBlock;

  struct Sample {
    Vec2 uv;         // the point, in [0,1)^2
    int column = 0;  // its cell
    int row = 0;
    float pdf = 0.0f;  // density with respect to du dv
    size_t key = 0;    // the cell's key (block-major position)
  };

  Distribution2D() = default;
  // weights: width * height non-negative values, row-major, row 0 first. All zero -> empty().
  Distribution2D(const std::vector<double>& weights, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return block_row_marginal_.empty(); }

  // Maps two uniform numbers in [0,1) to a point distributed in proportion to the weights.
  Sample sample(const Vec2& u) const { return sample_in_block(choose_block(u)); }

  // sample() in its two stages, for callers that keep per-cell data by key: once the block is known they
  // can prefetch its cells' data (keys first_key .. first_key + kBlock^2 - 1) while the block's line loads.
  struct BlockChoice {
    size_t block = 0;      // block row * block columns + block column
    float u_in_block = 0;  // u.x rescaled inside the block column's interval of the coarse CDF
    float v_in_block = 0;  // u.y rescaled inside the block row's interval
    size_t first_key() const { return block * kCellsPerBlock; }
  };
  BlockChoice choose_block(const Vec2& u) const;
  Sample sample_in_block(const BlockChoice& choice) const;
  // Density of sample() at a cell (with respect to du dv), and at a point (its cell's density).
  float pdf(int column, int row) const { return pdf_of_key(cell_key(column, row)); }
  float pdf(const Vec2& uv) const { return pdf(column_of(uv.x), row_of(uv.y)); }

  // Block-major key of a cell; keys lie in [0, key_count()), padding cells included.
  size_t cell_key(int column, int row) const {
    // Unsigned: column and row are >= 0, and / and % by a power of two are then shifts and masks.
    constexpr unsigned b = kBlock;
    const auto c = static_cast<unsigned>(column), r = static_cast<unsigned>(row);
    const size_t block = static_cast<size_t>(r / b) * static_cast<unsigned>(block_columns_) + c / b;
    return block * (b * b) + (r % b) * b + c % b;
  }
  size_t key_count() const { return static_cast<size_t>(block_columns_) * block_rows_ * kCellsPerBlock; }
  // pdf() of the cell with this key (0 for a padding cell).
  float pdf_of_key(size_t key) const {
    return empty() ? 0.0f : blocks_[key / kCellsPerBlock].pdf[key % kCellsPerBlock];
  }
  // The cell of a point (clamped to the grid; NaN gives cell 0). Clamped before the conversion to int,
  // which is undefined for NaN and out-of-range values.
  int column_of(float u) const {
    return static_cast<int>(
        nan_safe_clamp(u * static_cast<float>(width_), 0.0f, static_cast<float>(width_ - 1)));
  }
  int row_of(float v) const {
    return static_cast<int>(
        nan_safe_clamp(v * static_cast<float>(height_), 0.0f, static_cast<float>(height_ - 1)));
  }

 private:
  // Block column of block row `block_row` for u, and u rescaled inside it (the coarse conditional).
  int sample_block_column(int block_row, float u, float* u_in_column) const;

  int width_ = 0;
  int height_ = 0;
  int block_columns_ = 0;  // ceil(width / kBlock)
  int block_rows_ = 0;

  Distribution1D block_row_marginal_;  // over block rows
  struct CoarseEntry {
    float cdf = 0.0f;    // normalised CDF before block column i (entry block_columns is exactly 1)
    uint32_t guide = 0;  // the first index j >= 1 with cdf[j] > i / block_columns
  };
  std::vector<CoarseEntry> coarse_;  // per block row: block_columns + 1 entries
  // pdf(column, row) of a block's cells, row-major inside the block: one cache line per block.
  struct alignas(64) Block {
    float pdf[kCellsPerBlock] = {};
  };
  std::vector<Block> blocks_;  // block-major: block row * block_columns + block column
};

}  // namespace ochre
