#include "renderer/sampling/distribution_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ochre {

namespace {

constexpr double kBelowOne = 0x1.fffffffffffffp-1;  // the largest double below 1

// CDF inversion over a few non-negative weights (a block's rows, or a row's cells): the item i with
// cdf[i] <= u * total < cdf[i + 1], found by counting the CDF entries at or below u * total (no branch to
// mispredict), and u rescaled to [0,1) inside it. Zero-weight items have an empty interval and are never
// chosen; when rounding puts u * total at the total, the last positive item is taken, at its top.
template <int n>
int invert_small_cdf(const double (&weights)[n], double u, double* u_inside) {
  double cdf[n + 1];
  cdf[0] = 0.0;
  for (int i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + weights[i];
  const double target = u * cdf[n];
  int i = 0;
  for (int k = 1; k < n; ++k) i += cdf[k] <= target ? 1 : 0;
  if (!(target < cdf[i + 1])) {
    i = n - 1;
    while (i > 0 && !(weights[i] > 0.0)) --i;
    *u_inside = kBelowOne;
    return i;
  }
  *u_inside = std::min((target - cdf[i]) / weights[i], kBelowOne);
  return i;
}

// The coordinate (cell + offset) / n of a point inside `cell` of a grid of n cells, computed in double
// ((cell + 0.99999994) / n in float could round up into the next cell). If float rounding put it out of the
// cell as the grid sees it (floor(c * n) in float, as column_of() computes it) or at the next cell's bound,
// it is moved by ulps.
float coordinate(int cell, double offset, int n) {
  const float fn = static_cast<float>(n);
  const float upper = static_cast<float>(cell + 1) / fn;
  float c = static_cast<float>((cell + offset) / n);
  if (static_cast<int>(c * fn) == cell && c < upper) return c;
  if (!(c < upper)) c = std::nextafter(upper, 0.0f);
  while (c > 0.0f && static_cast<int>(c * fn) > cell) c = std::nextafter(c, 0.0f);
  while (static_cast<int>(c * fn) < cell) c = std::nextafter(c, 1.0f);
  return c;
}

}  // namespace

Distribution2D::Distribution2D(const std::vector<double>& weights, int width, int height)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || weights.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument("Distribution2D: weights must hold width * height values");
  block_columns_ = (width + kBlock - 1) / kBlock;
  block_rows_ = (height + kBlock - 1) / kBlock;
  const auto weight = [&](int column, int row) {
    return std::max(0.0, weights[static_cast<size_t>(row) * width + column]);
  };
  std::vector<double> block_weights(static_cast<size_t>(block_columns_) * block_rows_, 0.0);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column)
      block_weights[(row / kBlock) * block_columns_ + column / kBlock] += weight(column, row);

  // Coarse level: per block row, the conditional CDF over block columns with its guide entries.
  const size_t stride = static_cast<size_t>(block_columns_) + 1;
  std::vector<double> block_row_totals(static_cast<size_t>(block_rows_));
  coarse_.assign(stride * block_rows_, CoarseEntry{});
  std::vector<float> row_cdf(stride);
  std::vector<double> cdf(stride);
  for (int block_row = 0; block_row < block_rows_; ++block_row) {
    const double* w = &block_weights[static_cast<size_t>(block_row) * block_columns_];
    cdf[0] = 0.0;
    for (int x = 0; x < block_columns_; ++x) cdf[x + 1] = cdf[x] + w[x];
    const double total = cdf[block_columns_];
    block_row_totals[static_cast<size_t>(block_row)] = total;
    if (!(total > 0.0)) continue;  // never picked by the marginal
    for (int x = 0; x < block_columns_; ++x) row_cdf[x] = static_cast<float>(cdf[x] / total);
    row_cdf[block_columns_] = 1.0f;
    CoarseEntry* entries = &coarse_[block_row * stride];
    for (int k = 0; k <= block_columns_; ++k) {
      const float bound = static_cast<float>(static_cast<double>(k) / block_columns_);
      entries[k].cdf = row_cdf[k];
      entries[k].guide = static_cast<uint32_t>(std::upper_bound(row_cdf.begin() + 1, row_cdf.end(), bound) -
                                               row_cdf.begin());
    }
  }
  block_row_marginal_ = Distribution1D(block_row_totals);
  if (empty()) return;

  // Fine level: each cell's final density. P(block) is the probability sample() really gives the block: the
  // marginal's pmf times the width of the block's interval of the float CDF it inverts (exact in double).
  blocks_.assign(static_cast<size_t>(block_columns_) * block_rows_, Block{});
  const double cells = static_cast<double>(width) * static_cast<double>(height);
  for (int block_row = 0; block_row < block_rows_; ++block_row) {
    const CoarseEntry* entries = &coarse_[block_row * stride];
    for (int block_column = 0; block_column < block_columns_; ++block_column) {
      const size_t block = static_cast<size_t>(block_row) * block_columns_ + block_column;
      const double p_block = static_cast<double>(block_row_marginal_.pmf(static_cast<size_t>(block_row))) *
                             (static_cast<double>(entries[block_column + 1].cdf) -
                              static_cast<double>(entries[block_column].cdf));
      if (!(p_block > 0.0)) continue;
      for (int r = 0; r < kBlock; ++r)
        for (int c = 0; c < kBlock; ++c) {
          const int row = block_row * kBlock + r, column = block_column * kBlock + c;
          if (row >= height || column >= width) continue;  // padding: weight 0
          blocks_[block].pdf[r * kBlock + c] =
              static_cast<float>(p_block * weight(column, row) / block_weights[block] * cells);
        }
    }
  }
}

int Distribution2D::sample_block_column(int block_row, float u, float* u_in_column) const {
  const size_t stride = static_cast<size_t>(block_columns_) + 1;
  const CoarseEntry* e = &coarse_[block_row * stride];
  const int n = block_columns_;
  // The same search as Distribution1D::sample: the first CDF entry above u lies between the guide entries
  // of the buckets either side of u's (one bucket of margin for the rounding of u * n).
  const int k = std::min(static_cast<int>(u > 0.0f ? u * static_cast<float>(n) : 0.0f), n - 1);
  const uint32_t lo = e[k > 0 ? k - 1 : 0].guide;
  const uint32_t hi = std::min<uint32_t>(e[std::min(k + 2, n)].guide + 1, static_cast<uint32_t>(stride));
  const CoarseEntry* upper = std::upper_bound(
      e + lo, e + hi, u, [](float value, const CoarseEntry& entry) { return value < entry.cdf; });
  int column = std::clamp(static_cast<int>(upper - e) - 1, 0, n - 1);
  while (e[column + 1].cdf == e[column].cdf && column > 0) --column;  // skip zero-weight blocks
  const float w = e[column + 1].cdf - e[column].cdf;
  *u_in_column = w > 0.0f ? std::clamp((u - e[column].cdf) / w, 0.0f, 0.99999994f) : 0.0f;
  return column;
}

Distribution2D::BlockChoice Distribution2D::choose_block(const Vec2& u) const {
  BlockChoice choice;
  if (empty()) return choice;
  const int block_row = static_cast<int>(block_row_marginal_.sample(u.y, &choice.v_in_block));
  const int block_column = sample_block_column(block_row, u.x, &choice.u_in_block);
  choice.block = static_cast<size_t>(block_row) * block_columns_ + block_column;
  return choice;
}

Distribution2D::Sample Distribution2D::sample_in_block(const BlockChoice& choice) const {
  Sample s;
  if (empty()) return s;
  const float* pdf = blocks_[choice.block].pdf;
  // Inside the block: the row by the rows' sums (P(row | block)), then the column in that row.
  double row_sums[kBlock], cells[kBlock];
  for (int r = 0; r < kBlock; ++r) {
    row_sums[r] = 0.0;
    for (int c = 0; c < kBlock; ++c) row_sums[r] += pdf[r * kBlock + c];
  }
  double v_in_row = 0.0, u_in_cell = 0.0;
  const int r = invert_small_cdf(row_sums, choice.v_in_block, &v_in_row);
  for (int c = 0; c < kBlock; ++c) cells[c] = pdf[r * kBlock + c];
  const int c = invert_small_cdf(cells, choice.u_in_block, &u_in_cell);
  const int block_row = static_cast<int>(choice.block / block_columns_);
  const int block_column = static_cast<int>(choice.block % block_columns_);
  s.row = block_row * kBlock + r;
  s.column = block_column * kBlock + c;
  s.key = choice.first_key() + r * kBlock + c;
  s.pdf = pdf[r * kBlock + c];
  s.uv = {coordinate(s.column, u_in_cell, width_), coordinate(s.row, v_in_row, height_)};
  return s;
}

}  // namespace ochre
