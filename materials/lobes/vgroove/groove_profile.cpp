#include "materials/lobes/vgroove/groove_profile.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "materials/lobes/vgroove/vgroove.h"

namespace ochre {

void GrooveProfile::add(double y0, double z0, double y1, double z1, const Vec3d& normal) {
  segments_[count_++] = {y0, z0, y1, z1, normal};
}

void GrooveProfile::add(double y0, double z0, double y1, double z1) {
  // The profile runs left to right with the opening above: the normal is the direction turned by +90 deg.
  const double dy = y1 - y0, dz = z1 - z0, len = std::hypot(dy, dz);
  add(y0, z0, y1, z1, Vec3d(0.0, -dz / len, dy / len));
}

void GrooveProfile::finish() {
  const ProfileSegment &first = segments_[0], &last = segments_[count_ - 1];
  centre_ = 0.5 * (first.y0 + last.y1);
  half_width_ = 0.5 * (last.y1 - first.y0);
  top_ = first.z0;
}

GrooveProfile GrooveProfile::v(double alpha) {
  // The analytic model's geometry and normals, bit for bit (VGroove, Saint-Pierre et al. Eqs 1-2).
  const VGroove groove(alpha);
  const double h = groove.half_opening(), c = groove.depth();
  GrooveProfile p;
  p.add(-h, c, 0.0, 0.0, groove.facet_normal(1));
  p.add(0.0, 0.0, h, c, groove.facet_normal(2));
  p.finish();
  return p;
}

GrooveProfile GrooveProfile::asymmetric_v(double slope1, double slope2) {
  GrooveProfile p;
  p.add(-1.0 / std::tan(slope1), 1.0, 0.0, 0.0);
  p.add(0.0, 0.0, 1.0 / std::tan(slope2), 1.0);
  p.finish();
  return p;
}

GrooveProfile GrooveProfile::flat_bottom(double alpha, double bottom) {
  const VGroove groove(alpha);
  const double h = groove.half_opening(), c = groove.depth();
  const double cut = bottom * c, y = bottom * h;  // the walls keep the V's slope
  GrooveProfile p;
  p.add(-h, c - cut, -y, 0.0, groove.facet_normal(1));
  p.add(-y, 0.0, y, 0.0, Vec3d(0.0, 0.0, 1.0));
  p.add(y, 0.0, h, c - cut, groove.facet_normal(2));
  p.finish();
  return p;
}

GrooveProfile GrooveProfile::rounded(double alpha, int segments) {
  // Unit circle centred at (0, 1): the arc's half angle is the rim tangent's slope (pi - alpha) / 2.
  const double half = 0.5 * (std::numbers::pi - alpha);
  GrooveProfile p;
  const int n = std::min(std::max(segments, 2), kMaxSegments);
  for (int i = 0; i < n; ++i) {
    const double a0 = -half + 2.0 * half * i / n, a1 = -half + 2.0 * half * (i + 1) / n;
    p.add(std::sin(a0), 1.0 - std::cos(a0), std::sin(a1), 1.0 - std::cos(a1));
  }
  // Rims exactly level (the two ends were computed from +-half).
  p.segments_[n - 1].z1 = p.segments_[0].z0;
  p.finish();
  return p;
}

int GrooveProfile::trace(const Vec3d& e, double u, std::span<uint8_t> facets, Vec3d& exit) const {
  double py = centre_ + (2.0 * u - 1.0) * half_width_, pz = top_;
  Vec3d d = -e;
  int last = -1, count = 0;
  for (;;) {
    double best_t = std::numeric_limits<double>::infinity();
    int best = -1;
    for (int i = 0; i < count_; ++i) {
      if (i == last) continue;  // a ray cannot meet the flat facet it leaves
      const ProfileSegment& s = segments_[i];
      if (!(dot(d, s.normal) < 0.0)) continue;  // facets are one-sided: met from the opening's side
      // p + t d = a + w (b - a) in the (y, z) plane.
      const double ey = s.y1 - s.y0, ez = s.z1 - s.z0;
      const double denom = d.y * ez - d.z * ey;
      if (denom == 0.0) continue;
      const double qy = s.y0 - py, qz = s.z0 - pz;
      const double t = (qy * ez - qz * ey) / denom;
      const double w = (qy * d.z - qz * d.y) / denom;
      if (t > 0.0 && w >= -1e-12 && w <= 1.0 + 1e-12 && t < best_t) best_t = t, best = i;
    }
    if (best < 0) break;  // leaves through the opening
    if (count == static_cast<int>(facets.size())) return -1;
    py += best_t * d.y;
    pz += best_t * d.z;
    d = reflect(d, segments_[best].normal);
    facets[count++] = static_cast<uint8_t>(best);
    last = best;
  }
  exit = d;
  return count;
}

}  // namespace ochre
