#include "renderer/film/pixel_filter.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ochre {

namespace {

// Cells of the tabulated gaussian: 1/4096 of its 8-stddev width each, far below a pixel.
constexpr int kGaussianCells = 4096;

}  // namespace

PixelFilter PixelFilter::box(float radius) {
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw std::invalid_argument(fmt::format("box filter radius must be > 0 (got {})", radius));
  PixelFilter f;
  f.radius_ = radius;
  return f;
}

PixelFilter PixelFilter::gaussian(float stddev) {
  if (!(stddev > 0.0f) || !(stddev <= 64.0f))
    throw std::invalid_argument(fmt::format("gaussian filter stddev must be in (0, 64] (got {})", stddev));
  PixelFilter f;
  f.gaussian_ = true;
  f.stddev_ = stddev;
  f.radius_ = 4.0f * stddev;
  const double alpha = -1.0 / (2.0 * double(stddev) * stddev);
  const double bias = std::exp(alpha * double(f.radius_) * f.radius_);
  std::vector<double> weights(kGaussianCells);
  for (int i = 0; i < kGaussianCells; ++i) {
    const double x = (2.0 * (i + 0.5) / kGaussianCells - 1.0) * f.radius_;  // the cell's centre
    weights[i] = std::max(0.0, std::exp(alpha * x * x) - bias);
  }
  f.cells_ = Distribution1D(weights);
  return f;
}

float PixelFilter::sample_axis(float u) const {
  if (!gaussian_) return 0.5f + (2.0f * u - 1.0f) * radius_;
  float within = 0.0f;
  const size_t cell = cells_.sample(u, &within);
  return 0.5f + (2.0f * (static_cast<float>(cell) + within) / kGaussianCells - 1.0f) * radius_;
}

Vec2 PixelFilter::sample(Vec2 u) const {
  if (!gaussian_ && radius_ == 0.5f) return u;  // the pixel itself: the sample position unchanged
  return {sample_axis(u.x), sample_axis(u.y)};
}

std::string PixelFilter::description() const {
  return gaussian_ ? fmt::format("gaussian (stddev {}, radius {})", stddev_, radius_)
                   : fmt::format("box (radius {})", radius_);
}

}  // namespace ochre
