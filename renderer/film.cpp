#include "renderer/film.h"

#include <algorithm>
#include <cmath>

namespace ochre {

namespace {
constexpr double kScale = 0x1p40;
constexpr double kMaxMagnitude = 1e15;

__int128 to_fixed(double v) {
  v = std::clamp(v, -kMaxMagnitude, kMaxMagnitude);
  return static_cast<__int128>(std::nearbyint(v * kScale));
}
double from_fixed(__int128 v) {
  return static_cast<double>(v) / kScale;
}
}  // namespace

Film::Film(int width, int height)
    : width_(width), height_(height), pixels_(static_cast<size_t>(width) * height) {}

void Film::add_sample(int x, int y, const XYZ& xyz) {
  Pixel& p = pixels_[index(x, y)];
  p.xyz[0] += to_fixed(xyz.x);
  p.xyz[1] += to_fixed(xyz.y);
  p.xyz[2] += to_fixed(xyz.z);
  p.y2 += to_fixed(static_cast<double>(xyz.y) * xyz.y);
  ++p.count;
}

void Film::merge(const Film& other) {
  for (size_t i = 0; i < pixels_.size(); ++i) {
    for (int c = 0; c < 3; ++c) pixels_[i].xyz[c] += other.pixels_[i].xyz[c];
    pixels_[i].y2 += other.pixels_[i].y2;
    pixels_[i].count += other.pixels_[i].count;
  }
}

XYZ Film::mean(int x, int y) const {
  const Pixel& p = pixels_[index(x, y)];
  if (p.count == 0) return {0, 0, 0};
  const double n = static_cast<double>(p.count);
  return {static_cast<float>(from_fixed(p.xyz[0]) / n), static_cast<float>(from_fixed(p.xyz[1]) / n),
          static_cast<float>(from_fixed(p.xyz[2]) / n)};
}

double Film::variance_y(int x, int y) const {
  const Pixel& p = pixels_[index(x, y)];
  if (p.count < 2) return 0.0;
  const double n = static_cast<double>(p.count);
  const double mean = from_fixed(p.xyz[1]) / n;
  const double mean_sq = from_fixed(p.y2) / n;
  return std::max(0.0, (mean_sq - mean * mean) * n / (n - 1.0));
}

}  // namespace ochre
