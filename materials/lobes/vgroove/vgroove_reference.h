#pragma once
// Deterministic reference values of the V-groove model (no sampling): the hemispherical-directional
// reflectance R(theta, phi) integrated exactly over the entry position (Saint-Pierre et al. 2019,
// Eq 36: the integrand is constant between VGroove::breakpoints), and the bi-hemispherical reflectance
// (Eq 42) by Gauss-Legendre quadrature over the hemisphere. Every function evaluates several facet
// indices (wavelengths) at once, sharing the geometry.

#include <span>
#include <vector>

#include "materials/lobes/reflection_chain.h"
#include "materials/lobes/vgroove/vgroove.h"

namespace ochre {

// Eq 3: the direction (theta, phi) in the groove frame, phi measured from the y axis (across the
// grooves): e = (sin theta sin phi, sin theta cos phi, cos theta).
Vec3d groove_direction(double theta, double phi);

struct DirectionalReflectance {
  std::vector<double> reflectance;  // one per facet index
  int max_reflections = 0;          // the largest reflection count of any entry position
};

// R(theta, phi) of Eq 36 for the direction e (unit, e.z > 0). Rays needing more than
// `reflection_limit` reflections are absorbed (Table 3 of the paper; 0 = no limit).
DirectionalReflectance directional_reflectance(const VGroove& groove, const Vec3d& e, ChainModel model,
                                               std::span<const FacetIndex> facets, int reflection_limit = 0);

// Eq 42: (1/pi) integral of R(theta, phi) cos(theta) over the hemisphere, by an n x n Gauss-Legendre
// rule in (sin^2 theta, phi) over a quarter of the hemisphere (R is symmetric in phi -> -phi and
// phi -> pi - phi). R has kinks where reflection counts change, so the error falls as about n^-2:
// n = 96 gives about 1e-5.
std::vector<double> bihemispherical_reflectance(const VGroove& groove, ChainModel model,
                                                std::span<const FacetIndex> facets, int reflection_limit = 0,
                                                int quadrature_points = 96);

}  // namespace ochre
