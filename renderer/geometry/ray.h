#pragma once
// Ray: an origin, a direction and the parametric interval [tmin, tmax] a query searches.

#include <cmath>

#include "materials/core/vec3.h"

namespace ochre {

struct Ray {
  Vec3 origin;
  Vec3 dir;  // need not be unit length; t is measured in units of |dir|
  float tmin = 0;
  float tmax = INFINITY;
};

}  // namespace ochre
