#pragma once
// Ray: an origin, a direction and the parametric interval [tmin, tmax] a query searches; a ray spawned from
// a surface also names the triangle it leaves (renderer/geometry/accel.h, spawn_ray), which the query then
// never reports and near which it checks hits exactly.

#include <cmath>
#include <cstdint>

#include "materials/core/vec3.h"

namespace ochre {

struct Ray {
  Vec3 origin;
  Vec3 dir;  // need not be unit length; t is measured in units of |dir|
  float tmin = 0;
  float tmax = INFINITY;
  // The triangle the ray leaves (mesh index and triangle index), or kNoTriangle for camera rays.
  static constexpr uint32_t kNoTriangle = ~0u;
  uint32_t from_mesh = kNoTriangle, from_triangle = kNoTriangle;
};

}  // namespace ochre
