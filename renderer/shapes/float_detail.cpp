#include "renderer/shapes/float_detail.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ochre {

namespace {

// The coarsest rounding of a vertex's coordinates allowed, as a fraction of the median edge.
constexpr double kMaxSpacingPerEdge = 1e-3;
// Edges measured for the median: every triangle up to this many, a regular sample beyond.
constexpr size_t kSampledTriangles = 65536;

float largest_component(const Vec3& v) {
  return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z)));
}

}  // namespace

std::optional<std::string> float_detail_warning(const std::string& where, const std::vector<Vec3>& positions,
                                                const std::vector<uint32_t>& indices) {
  float magnitude = 0.0f;
  for (const Vec3& p : positions) magnitude = std::max(magnitude, largest_component(p));
  const double spacing = std::nextafter(magnitude, std::numeric_limits<float>::infinity()) - magnitude;
  const size_t triangles = indices.size() / 3;
  if (triangles == 0 || !std::isfinite(spacing)) return std::nullopt;
  const size_t stride = std::max<size_t>(1, triangles / kSampledTriangles);
  std::vector<float> edges;
  for (size_t t = 0; t < triangles; t += stride)
    for (int k = 0; k < 3; ++k) {
      edges.push_back(
          largest_component(positions[indices[3 * t + k]] - positions[indices[3 * t + (k + 1) % 3]]));
    }
  if (edges.empty()) return std::nullopt;
  std::nth_element(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2), edges.end());
  const double median = edges[edges.size() / 2];
  if (spacing <= kMaxSpacingPerEdge * median) return std::nullopt;
  if (median == 0.0)  // most edges collapsed: the rounding left no length to compare with
    return fmt::format(
        "{}: single precision cannot hold this mesh's detail where it lies: its coordinates reach {:.4g} in "
        "the file, where single-precision numbers are {:.3g} apart, and most of its edges are shorter than "
        "that: "
        "they collapse. Export the mesh near the origin (photogrammetry tools offer a local shift) and place "
        "it with \"transform\": {{\"translate\": [x, y, z]}}, which ochre applies in double precision "
        "(docs/scene-format.md, \"Coordinate range\")",
        where, magnitude, spacing);
  return fmt::format(
      "{}: single precision cannot hold this mesh's detail where it lies: its coordinates reach {:.4g} in "
      "the "
      "file, where single-precision numbers are {:.3g} apart, {:.2g} of its median edge ({:.3g}): its "
      "vertices "
      "are rounded to that step. Export the mesh near the origin (photogrammetry tools offer a local shift) "
      "and "
      "place it with \"transform\": {{\"translate\": [x, y, z]}}, which ochre applies in double precision "
      "(docs/scene-format.md, \"Coordinate range\")",
      where, magnitude, spacing, spacing / median, median);
}

}  // namespace ochre
