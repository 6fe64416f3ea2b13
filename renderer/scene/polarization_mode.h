#pragma once
// Polarization modes (model only what a scene needs: docs/architecture.md, 'Design rules';
// docs/polarization.md, 'Modes'):
//   off       : scalar throughput; every element acts as a depolarizer (filters pass half);
//   intensity : the first row of the Mueller product (4 floats per wavelength); exact S0;
//   stokes    : the full Mueller product; S0..S3 at the sensor.
// auto picks stokes when a Stokes output is requested; intensity when a polarizer filter is in the scene
// or a material polarizes enough to change the image's intensities (PolarizationSignificance); off
// otherwise.

#include <string>

#include "renderer/scene/render_settings.h"

namespace ochre {

enum class PolarizationMode { kOff, kIntensity, kStokes };

const char* polarization_mode_name(PolarizationMode mode);

// How much the scene's polarizing materials can change intensities: the largest mean diattenuation and
// polarizance of their closures (renderer/scene/polarization_significance.h estimates them). Their product
// bounds the relative change of a path's contribution through two polarizing vertices.
struct PolarizationSignificance {
  double diattenuation = 0.0;  // |M[0][1..3]| / M00
  double polarizance = 0.0;    // |M[1..3][0]| / M00
  bool delta_lobes = false;    // a polarizing material has a mirror or glass lobe: not estimated, significant
  double bound() const { return delta_lobes ? 1.0 : diattenuation * polarizance; }
};

// Below this bound auto leaves polarization off: the intensities change by less than a thousandth on the
// paths that meet two polarizing vertices (the default cave: bound ~1e-4, image mean 2e-5).
inline constexpr double kPolarizationSignificant = 1e-3;

// What the scene holds that polarizes.
struct PolarizationNeeds {
  bool filters = false;    // a polarizer on a light or a mesh, or an analyzer on the camera
  bool materials = false;  // some material has a polarizing lobe
  PolarizationSignificance significance;
};

struct PolarizationChoice {
  PolarizationMode mode = PolarizationMode::kOff;
  std::string reason;  // e.g. "auto: no material or filter polarizes"
};

PolarizationChoice choose_polarization_mode(PolarizationSetting requested, const PolarizationNeeds& needs,
                                            bool stokes_output_requested);

}  // namespace ochre
