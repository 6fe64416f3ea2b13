#include "renderer/distribution_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ochre {

Distribution2D::Distribution2D(const std::vector<double>& weights, int width, int height)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || weights.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument("Distribution2D: weights must hold width * height values");
  conditional_.reserve(static_cast<size_t>(height));
  std::vector<double> row_totals(static_cast<size_t>(height));
  std::vector<double> row(static_cast<size_t>(width));
  for (int y = 0; y < height; ++y) {
    const auto begin = weights.begin() + static_cast<std::ptrdiff_t>(y) * width;
    std::copy(begin, begin + width, row.begin());
    conditional_.emplace_back(row);
    row_totals[static_cast<size_t>(y)] = conditional_.back().total();
  }
  marginal_ = Distribution1D(row_totals);
  if (empty()) return;
  cell_pdf_.resize(weights.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      cell_pdf_[static_cast<size_t>(y) * width + x] =
          marginal_.pmf(static_cast<size_t>(y)) *
          conditional_[static_cast<size_t>(y)].pmf(static_cast<size_t>(x)) * static_cast<float>(width_) *
          static_cast<float>(height_);
}

Distribution2D::Sample Distribution2D::sample(const Vec2& u) const {
  Sample s;
  float v_in_row = 0.0f, u_in_column = 0.0f;
  s.row = static_cast<int>(marginal_.sample(u.y, &v_in_row));
  s.column = static_cast<int>(conditional_[static_cast<size_t>(s.row)].sample(u.x, &u_in_column));
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
