#include "renderer/integrator/path_guide.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "materials/core/pi.h"

namespace ochre {

namespace {

// A cell for about every kRecordsPerCell records, at most kMaxCells over the box of the training points
// (2 MB of histograms), each used from kMinRecords observations on; a uniform floor keeps every direction
// of a used cell possible.
constexpr double kRecordsPerCell = 256;
constexpr double kMaxCells = 4096;
constexpr int kMaxCellsPerAxis = 256;
constexpr uint32_t kMinRecords = 64;
constexpr double kUniformFloor = 0.02;
// Fixed point of the sums: the largest observation maps to 2^36, so that even 2^24 records of it in one
// cell fit in 64 bits; integer sums make the guide independent of the records' order.
constexpr double kFixedPointTop = 0x1p36;
constexpr float kBinSolidAngle = 4.0f * kPi / PathGuide::kBins;

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// An observation's weight in its bin, radiance over the density it was sampled with: the Monte Carlo
// estimate of the bin's integral of incident radiance. -1 for a record without a usable figure.
double weight_of(const GuideRecord& r) {
  const double w = double(r.radiance) / double(r.pdf);
  return std::isfinite(w) && w >= 0.0 && finite(r.p) && finite(r.dir) ? w : -1.0;
}

// The unit direction at the centre of every bin, by component (the product's loop runs over them).
struct BinCentres {
  alignas(32) std::array<float, PathGuide::kBins> x, y, z;
  BinCentres() {
    for (int b = 0; b < PathGuide::kBins; ++b) {
      const int iz = b / PathGuide::kPhiBins, iphi = b % PathGuide::kPhiBins;
      const float cz = -1.0f + (static_cast<float>(iz) + 0.5f) * (2.0f / PathGuide::kZBins);
      const float phi = (static_cast<float>(iphi) + 0.5f) * (2.0f * kPi / PathGuide::kPhiBins) - kPi;
      const float r = std::sqrt(std::max(0.0f, 1.0f - cz * cz));
      x[b] = r * std::cos(phi);
      y[b] = r * std::sin(phi);
      z[b] = cz;
    }
  }
};
const BinCentres kCentres;

}  // namespace

int PathGuide::bin_of(const Vec3& dir) {
  const int iz = std::clamp(static_cast<int>((dir.z + 1.0f) * (0.5f * kZBins)), 0, kZBins - 1);
  const float phi = std::atan2(dir.y, dir.x) + kPi;  // [0, 2 pi]
  const int iphi = std::clamp(static_cast<int>(phi * (kPhiBins / (2.0f * kPi))), 0, kPhiBins - 1);
  return iz * kPhiBins + iphi;
}

PathGuide PathGuide::build(const std::vector<std::vector<GuideRecord>>& records) {
  PathGuide guide;
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  double top = 0.0;
  size_t usable_records = 0;
  for (const auto& list : records)
    for (const GuideRecord& r : list) {
      const double w = weight_of(r);
      if (w < 0.0) continue;
      ++usable_records;
      lo = min(lo, r.p);
      hi = max(hi, r.p);
      top = std::max(top, w);
    }
  if (!(top > 0.0)) return guide;  // nothing learned: no cells, no guiding

  // Cells of about equal edge; a flat box (a plane) gets one layer. A hair beyond the farthest point, so
  // that it falls inside the last cell.
  const Vec3 extent = hi - lo;
  const float longest = std::max({extent.x, extent.y, extent.z, 1e-6f});
  const Vec3 padded{std::max(extent.x, 1e-3f * longest), std::max(extent.y, 1e-3f * longest),
                    std::max(extent.z, 1e-3f * longest)};
  const double target_cells = std::clamp(double(usable_records) / kRecordsPerCell, 1.0, kMaxCells);
  const double edge = std::cbrt(double(padded.x) * padded.y * padded.z / target_cells);
  guide.lo_ = lo;
  for (int axis = 0; axis < 3; ++axis) {
    guide.dims_[axis] = std::clamp(static_cast<int>(std::ceil(padded[axis] / edge)), 1, kMaxCellsPerAxis);
    guide.cell_size_[axis] = padded[axis] * (1.0f + 1e-5f) / static_cast<float>(guide.dims_[axis]);
  }

  const size_t cell_count = size_t(guide.dims_[0]) * guide.dims_[1] * guide.dims_[2];
  std::vector<uint64_t> sums(cell_count * kBins, 0);
  std::vector<uint32_t> counts(cell_count, 0);
  const double scale = kFixedPointTop / top;
  guide.cells_.resize(cell_count);  // before cell_index, which finds no cell in an empty grid
  for (const auto& list : records)
    for (const GuideRecord& r : list) {
      const double w = weight_of(r);
      const ptrdiff_t index = w < 0.0 ? -1 : guide.cell_index(r.p);
      if (index < 0) continue;  // a record of no light (0) counts: dark directions are learned too
      sums[size_t(index) * kBins + bin_of(r.dir)] += static_cast<uint64_t>(std::llround(w * scale));
      ++counts[size_t(index)];
    }
  for (size_t i = 0; i < cell_count; ++i) {
    if (counts[i] < kMinRecords) continue;
    double total = 0.0;
    for (int b = 0; b < kBins; ++b) total += double(sums[i * kBins + b]);
    if (!(total > 0.0)) continue;
    const double floor = kUniformFloor * total / kBins;
    const double norm = 1.0 / (total + floor * kBins);
    Cell& cell = guide.cells_[i];
    for (int b = 0; b < kBins; ++b)
      cell.pmf[b] = static_cast<float>((double(sums[i * kBins + b]) + floor) * norm);
    cell.usable = true;
  }
  return guide;
}

ptrdiff_t PathGuide::cell_index(const Vec3& p) const {
  if (cells_.empty()) return -1;
  std::array<int, 3> c{};
  for (int axis = 0; axis < 3; ++axis) {
    const float t = (p[axis] - lo_[axis]) / cell_size_[axis];
    if (!(t >= 0.0f) || !(t < static_cast<float>(dims_[axis]))) return -1;  // outside, or NaN
    c[axis] = std::min(static_cast<int>(t), dims_[axis] - 1);
  }
  return static_cast<ptrdiff_t>((size_t(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0]);
}

ptrdiff_t PathGuide::prefetch(const Vec3& p) const {
  const ptrdiff_t index = cell_index(p);
  if (index < 0) return index;
  const char* bytes = reinterpret_cast<const char*>(&cells_[size_t(index)]);
  for (size_t line = 0; line < sizeof(Cell); line += 64) __builtin_prefetch(bytes + line);
  return index;
}

bool PathGuide::product(const Cell& cell, const Vec3& n, Product* out) {
  for (int b = 0; b < kBins; ++b) {
    const float c = kCentres.x[b] * n.x + kCentres.y[b] * n.y + kCentres.z[b] * n.z;
    out->weight[b] = cell.pmf[b] * (c > 0.0f ? c : 0.0f);
  }
  // Eight partial sums in a fixed order: the loops vectorise, and the total is the same bits everywhere.
  std::array<float, 8> partial{};
  for (int b = 0; b < kBins; b += 8)
    for (int l = 0; l < 8; ++l) partial[l] += out->weight[b + l];
  out->total = ((partial[0] + partial[1]) + (partial[2] + partial[3])) +
               ((partial[4] + partial[5]) + (partial[6] + partial[7]));
  return out->total > 0.0f;
}

Vec3 PathGuide::sample(const Product& product, float u_bin, const Vec2& u, float* pdf) {
  const float target = u_bin * product.total;
  int bin = -1;
  float running = 0.0f;
  for (int b = 0; b < kBins; ++b) {
    if (!(product.weight[b] > 0.0f)) continue;
    bin = b;  // the last bin with weight, should rounding carry the target past the end
    running += product.weight[b];
    if (running > target) break;
  }
  const int iz = bin / kPhiBins, iphi = bin % kPhiBins;
  const float z = std::clamp(-1.0f + (static_cast<float>(iz) + u.x) * (2.0f / kZBins), -1.0f, 1.0f);
  const float phi = (static_cast<float>(iphi) + u.y) * (2.0f * kPi / kPhiBins) - kPi;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const Vec3 dir{r * std::cos(phi), r * std::sin(phi), z};
  *pdf = PathGuide::pdf(product, dir);  // the bin pdf() finds for this direction, as MIS will
  return dir;
}

float PathGuide::pdf(const Product& product, const Vec3& dir) {
  return product.weight[bin_of(dir)] / (product.total * kBinSolidAngle);
}

size_t PathGuide::usable_cells() const {
  return static_cast<size_t>(
      std::count_if(cells_.begin(), cells_.end(), [](const Cell& c) { return c.usable; }));
}

}  // namespace ochre
