#pragma once
// The dry-powder BRDF (materials/lobes/powder/powder_model.h, default options) at every measurement's
// geometry and wavelength for a set of the six fitted parameters, split into its volume part (before A_v)
// and surface part (before A_s'): the BRDF is A_v volume + A_s' surface, linear in both amplitudes.

#include <vector>

#include "tools/fit/fit_pigment.h"
#include "tools/fit/measurements.h"
#include "tools/fit/powder_fit_params.h"

namespace ochre {

struct PowderParts {
  std::vector<double> volume, surface;  // per measurement, 1/sr per unit amplitude (surface: per um^2)
};

// Only g, kappa, radius and correlation_length of `values` matter here.
PowderParts powder_parts(const PowderValues& values, const std::vector<Measurement>& data,
                         const FitPigment& pigment);

// The BRDF (1/sr) at each measurement.
std::vector<double> powder_brdf_values(const PowderValues& values, const std::vector<Measurement>& data,
                                       const FitPigment& pigment);

}  // namespace ochre
