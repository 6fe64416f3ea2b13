#pragma once
// A unit direction in double precision for the half-space simulation. The simulation keeps its own
// small vector type so that it shares no code with the renderer's materials it is meant to check.
// Frame: z is the outward surface normal; the medium is z < 0.

#include <algorithm>
#include <cmath>

namespace ochre::halfspace {

struct Direction {
  double x = 0.0, y = 0.0, z = 1.0;
};

inline double dot(const Direction& a, const Direction& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// mu = cos theta; phi = relative azimuth measured from the +x half-plane. With wi at phi = 0, a wo at
// phi = 0 lies on the same side as wi (backscatter), phi = pi on the opposite side (forward).
inline Direction direction_from_angles(double mu, double phi) {
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), mu};
}

}  // namespace ochre::halfspace
