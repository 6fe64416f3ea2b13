#pragma once
// Lightness profiles of the hemispherical-directional reflectance (Saint-Pierre et al. 2019, Fig 9):
// L* of R(theta, phi) under D65 (vgroove_colour.h) versus theta, looking across the grooves (phi = 0)
// and along them (phi = 90 degrees), for several chain models. R is symmetric under phi -> -phi and
// phi -> 180 - phi, so these are the horizontal and vertical diameters of the maps.

#include <vector>

#include "materials/lobes/reflection_chain.h"
#include "tools/vgroove/vgroove_material.h"

namespace ochre {

struct ProfilePoint {
  double phi_deg, theta_deg;
  ChainModel model;
  double lightness;
};

// Rows ordered by phi (0 then 90), model (as given), theta (0, step, ... below 90).
std::vector<ProfilePoint> lightness_profiles(const VGrooveMaterial& material, double alpha_deg,
                                             const std::vector<ChainModel>& models, double theta_step_deg);

}  // namespace ochre
