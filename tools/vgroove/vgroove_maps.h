#pragma once
// Hemispherical-directional reflectance maps of a V-groove surface (Saint-Pierre et al. 2019, Figs 6
// and 8): every viewing direction (theta, phi) is drawn at the point of the Lambert azimuthal equal-area
// projection (Eq 38)
//   u = 2 sin(theta / 2) cos(phi),  v = 2 sin(theta / 2) sin(phi)
// of a disk of radius sqrt 2, u to the right (phi = 0: across the grooves), v up (phi = 90 degrees:
// along the grooves). Two maps: the sRGB colour of R(theta, phi) under D65 (vgroove_colour.h) and the
// largest number of reflections any entering ray makes (count_colour()). Pixels outside the disk are
// white.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "materials/lobes/reflection_chain.h"
#include "tools/vgroove/vgroove_material.h"

namespace ochre {

struct LambertDirection {
  double theta, phi;  // radians
};

// The direction at the centre of pixel (column, row) of a size x size map (row 0 = top), or nothing
// outside the disk. With an odd size the centre pixel is theta = 0.
std::optional<LambertDirection> lambert_pixel_direction(int column, int row, int size);

// The palette of the reflection-count maps: 1 light grey (as in the paper), 2 blue, 3 orange, 4 red,
// more than 4 purple; 0 (outside the disk) white.
std::array<std::uint8_t, 3> count_colour(int reflections);

struct ReflectanceMaps {
  int size = 0;
  std::vector<std::uint8_t> colour;  // RGB, 8 bits, row 0 = top
  std::vector<std::uint8_t> counts;  // RGB, 8 bits
};

// Rows are computed in parallel; every pixel is independent, so the result does not depend on threads.
ReflectanceMaps reflectance_maps(const VGrooveMaterial& material, double alpha_deg, ChainModel model,
                                 int size);

}  // namespace ochre
