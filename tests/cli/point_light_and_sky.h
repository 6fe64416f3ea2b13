#pragma once
// A point light (intensity I at height h) and a constant environment (radiance Le) over a Lambert plane of
// albedo rho, seen from above through an orthographic camera: L = rho / pi * I cos / r^2 + rho Le at every
// point, a closed form against which the integrator's light sampling, MIS and scattering are checked.

#include <string>

namespace ochre::test {

struct PointLightAndSky {
  double worst = 0;          // largest per-pixel relative error
  double mean = 0;           // image mean
  double expected_mean = 0;  // the closed form's
};

// Renders the scene (16x16 pixels, `integrator_fields` the members of its "integrator" block, e.g.
// `"spp": 1024, "max_depth": 1`) and compares every pixel with the closed form averaged over it.
PointLightAndSky render_point_light_and_sky(const std::string& integrator_fields);

}  // namespace ochre::test
