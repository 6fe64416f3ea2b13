#pragma once
// GrooveProfile: one period of a groove surface's cross-section as a polyline in the (y, z) plane of the
// groove frame (x along the grooves), for the explicit `microgroove` lobe. The two end points are the
// rims, at the same height `top`; every other point lies strictly below it, so a ray that enters
// through the opening can leave only through it: the period's neighbours are never reached. The ray is
// traced through the actual facets (no unfolding), reflecting at each, until it leaves.
//
// Profiles: a symmetric V (the geometry and facet normals of VGroove, so the explicit and the analytic
// models agree ray for ray), an asymmetric V, a V with a flat bottom, and a rounded (circular-arc)
// groove.

#include <array>
#include <cstdint>
#include <span>

#include "materials/core/vec3d.h"

namespace ochre {

struct ProfileSegment {
  double y0, z0, y1, z1;  // from (y0, z0) to (y1, z1), left to right
  Vec3d normal;           // (0, n_y, n_z): the unit normal on the side of the opening
};

class GrooveProfile {
 public:
  static constexpr int kMaxSegments = 64;

  // Symmetric V of dihedral angle alpha (radians), facets of unit width, apex at the origin.
  static GrooveProfile v(double alpha);
  // Asymmetric V: the left facet descends at slope1 and the right one rises at slope2 (radians from the
  // mean surface, each in (0, pi/2)); depth 1.
  static GrooveProfile asymmetric_v(double slope1, double slope2);
  // The symmetric V with its lowest `bottom` fraction (0..1) of the depth cut flat.
  static GrooveProfile flat_bottom(double alpha, double bottom);
  // A circular arc whose tangents at the rims meet at the dihedral angle alpha, as `segments` chords.
  static GrooveProfile rounded(double alpha, int segments);

  int segment_count() const { return count_; }
  const ProfileSegment& segment(int i) const { return segments_[i]; }
  double opening_centre() const { return centre_; }
  double opening_half_width() const { return half_width_; }
  double top() const { return top_; }

  // Traces the ray entering the opening at y = centre + (2 u - 1) half_width along -e (e.z > 0). Writes
  // the index of each facet met, in order, into `facets` and returns their count, or -1 when the path
  // needs more reflections than `facets` holds. `exit` receives the direction in which it leaves.
  int trace(const Vec3d& e, double u, std::span<uint8_t> facets, Vec3d& exit) const;

 private:
  void add(double y0, double z0, double y1, double z1);
  void add(double y0, double z0, double y1, double z1, const Vec3d& normal);
  void finish();

  std::array<ProfileSegment, kMaxSegments> segments_;
  int count_ = 0;
  double centre_ = 0.0, half_width_ = 0.0, top_ = 0.0;
};

}  // namespace ochre
