#pragma once
// ochre-fit's own test data: the dry-powder BRDF of known parameters on a goniophotometer-like grid, with
// multiplicative Gaussian noise (docs/tools.md, ochre-fit powder --synthesize).

#include <cstdint>
#include <vector>

#include "tools/fit/fit_pigment.h"
#include "tools/fit/measurements.h"
#include "tools/fit/powder_fit_params.h"

namespace ochre {

// The geometries, light at azimuth 0: theta_i in {0, 20, 40, 60} degrees; for each, the planes through the
// normal at azimuths {0, 30, 60, 90, 135} degrees with theta_o from -70 to 70 in steps of 10 (negative on
// the light's side: phi_o = the plane's azimuth, else + 180), and the backscattering peak in detail,
// theta_o = theta_i - 10 ... theta_i + 10 in steps of 2 on the light's side of the plane of incidence.
// Repeated directions appear once. One measurement per geometry and wavelength, brdf left 0.
std::vector<Measurement> goniophotometer_grid(const std::vector<double>& lambdas_nm);

// brdf = the model's value x (1 + noise z), z standard normal (Box-Muller on std::mt19937_64, which the
// C++ standard specifies bit for bit: the same numbers on every platform for a seed).
void synthesize_brdf(std::vector<Measurement>& grid, const PowderValues& values, const FitPigment& pigment,
                     double noise, uint64_t seed);

}  // namespace ochre
