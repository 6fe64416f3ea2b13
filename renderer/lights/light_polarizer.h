#pragma once
// An ideal linear polarizer in front of a light (point, spot or area light; scene key "polarizer": {"axis":
// [x, y, z]}): it passes half of the unpolarized emission, fully linearly polarized along its transmission
// axis projected perpendicular to the direction the light leaves in. A ray leaving along the axis itself
// is blocked (both transverse field components are perpendicular to the axis).

#include <optional>

#include "materials/core/vec3.h"
#include "spectra/sampled_spectrum.h"

namespace ochre {

// Light entering a path segment: unpolarized radiance, or radiance fully linearly polarized along a
// world axis perpendicular to the segment.
struct IncomingLight {
  SampledSpectrum radiance;  // S0
  bool polarized = false;
  Vec3 axis;  // world-space polarization axis when polarized (unit, perpendicular to the propagation)
};

// Emission `radiance` leaving along the unit direction `d`, through the polarizer when there is one.
inline IncomingLight filtered_emission(const std::optional<Vec3>& polarizer_axis, const Vec3& d,
                                       const SampledSpectrum& radiance) {
  IncomingLight light{radiance, false, {}};
  if (!polarizer_axis) return light;
  const Vec3 transverse = *polarizer_axis - d * dot(*polarizer_axis, d);
  const float len = length(transverse);
  if (!(len > 1e-6f)) return {SampledSpectrum(0.0f), false, {}};
  light.radiance = radiance * 0.5f;
  light.polarized = true;
  light.axis = transverse / len;
  return light;
}

}  // namespace ochre
