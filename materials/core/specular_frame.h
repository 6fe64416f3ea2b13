#pragma once
// The Stokes reference axis of a Fresnel interaction: the s direction, perpendicular to the plane of
// incidence spanned by the incident direction and the (micro)normal m. The same vector serves as the
// x axis of the incident beam (propagating along -wi) and of the reflected or refracted beam
// (propagating along wo), each with y = cross(d, x): the frames in which the Fresnel Mueller matrices
// of materials/lobes/fresnel.h hold (docs/polarization.md).

#include <cmath>

#include "materials/core/frame.h"
#include "materials/core/vec3.h"

namespace ochre {

inline Vec3 s_polarization_axis(const Vec3& wi, const Vec3& m) {
  const Vec3 s = cross(wi, m);
  const float len2 = dot(s, s);
  // At normal incidence every direction perpendicular to m is an s direction (the Fresnel matrix is
  // then the same for all of them); any perpendicular of m will do.
  if (!(len2 > 1e-20f)) return Frame::from_normal(m).s;
  return s / std::sqrt(len2);
}

}  // namespace ochre
