#include "renderer/distribution_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ochre {

Distribution2D::Distribution2D(const std::vector<double>& weights, int width, int height)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || weights.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument("Distribution2D: weights must hold width * height values");
  const size_t stride = static_cast<size_t>(width) + 1;
  std::vector<double> row_totals(static_cast<size_t>(height));
  rows_.assign(stride * height, RowEntry{});
  std::vector<float> row_cdf(stride);
  std::vector<double> cdf(stride);
  for (int y = 0; y < height; ++y) {
    const double* w = &weights[static_cast<size_t>(y) * width];
    cdf[0] = 0.0;
    for (int x = 0; x < width; ++x) cdf[x + 1] = cdf[x] + std::max(0.0, w[x]);
    const double total = cdf[width];
    row_totals[static_cast<size_t>(y)] = total;
    if (!(total > 0.0)) continue;  // never picked by the marginal
    for (int x = 0; x < width; ++x) row_cdf[x] = static_cast<float>(cdf[x] / total);
    row_cdf[width] = 1.0f;
    RowEntry* entries = &rows_[y * stride];
    for (int k = 0; k <= width; ++k) {
      const float bound = static_cast<float>(static_cast<double>(k) / width);
      entries[k].cdf = row_cdf[k];
      entries[k].guide = static_cast<uint32_t>(std::upper_bound(row_cdf.begin() + 1, row_cdf.end(), bound) -
                                               row_cdf.begin());
    }
  }
  marginal_ = Distribution1D(row_totals);
  if (empty()) return;
  cell_pdf_.resize(weights.size());
  for (int y = 0; y < height; ++y) {
    const float row_pmf = marginal_.pmf(static_cast<size_t>(y));
    const RowEntry* entries = &rows_[y * stride];
    for (int x = 0; x < width; ++x)
      cell_pdf_[static_cast<size_t>(y) * width + x] = row_pmf * (entries[x + 1].cdf - entries[x].cdf) *
                                                      static_cast<float>(width_) *
                                                      static_cast<float>(height_);
  }
}

int Distribution2D::sample_column(int row, float u, float* u_in_column) const {
  const size_t stride = static_cast<size_t>(width_) + 1;
  const RowEntry* e = &rows_[row * stride];
  // The same search as Distribution1D::sample: the first CDF entry above u lies between the guide entries
  // of the buckets either side of u's (one bucket of margin for the rounding of u * width).
  const int k = std::min(static_cast<int>(u > 0.0f ? u * static_cast<float>(width_) : 0.0f), width_ - 1);
  const uint32_t lo = e[k > 0 ? k - 1 : 0].guide;
  const uint32_t hi = std::min<uint32_t>(e[std::min(k + 2, width_)].guide + 1, static_cast<uint32_t>(stride));
  const RowEntry* upper = std::upper_bound(
      e + lo, e + hi, u, [](float value, const RowEntry& entry) { return value < entry.cdf; });
  int column = std::clamp(static_cast<int>(upper - e) - 1, 0, width_ - 1);
  while (e[column + 1].cdf == e[column].cdf && column > 0) --column;  // skip zero-weight cells
  const float w = e[column + 1].cdf - e[column].cdf;
  *u_in_column = w > 0.0f ? std::clamp((u - e[column].cdf) / w, 0.0f, 0.99999994f) : 0.0f;
  return column;
}

Distribution2D::Sample Distribution2D::sample(const Vec2& u) const {
  Sample s;
  if (empty()) return s;
  float v_in_row = 0.0f, u_in_column = 0.0f;
  s.row = static_cast<int>(marginal_.sample(u.y, &v_in_row));
  s.column = sample_column(s.row, u.x, &u_in_column);
  // Computed in double: (cell + 0.99999994) / n in float could round up into the next cell.
  const auto coordinate = [](int cell, float offset, int n) {
    const float c = static_cast<float>((cell + static_cast<double>(offset)) / n);
    return std::min(c, std::nextafter(static_cast<float>(cell + 1) / n, 0.0f));
  };
  s.uv = {coordinate(s.column, u_in_column, width_), coordinate(s.row, v_in_row, height_)};
  s.pdf = pdf(s.column, s.row);
  return s;
}

float Distribution2D::pdf(int column, int row) const {
  if (empty()) return 0.0f;
  return cell_pdf_[static_cast<size_t>(row) * width_ + column];
}

float Distribution2D::pdf(const Vec2& uv) const {
  const int column = std::clamp(static_cast<int>(uv.x * static_cast<float>(width_)), 0, width_ - 1);
  const int row = std::clamp(static_cast<int>(uv.y * static_cast<float>(height_)), 0, height_ - 1);
  return pdf(column, row);
}

}  // namespace ochre
