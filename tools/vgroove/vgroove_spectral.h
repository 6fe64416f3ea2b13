#pragma once
// The V-groove's colour seen from one direction: the hemispherical-directional reflectance R(theta, phi)
// (Saint-Pierre et al. 2019, Eq 36) at the colour wavelengths (vgroove_colour.h), as L*a*b*.

#include <span>
#include <vector>

#include "materials/lobes/vgroove/vgroove_reference.h"
#include "spectra/ciede2000.h"
#include "tools/vgroove/vgroove_material.h"

namespace ochre {

// The facet index at each of the wavelengths.
std::vector<FacetIndex> facets_at(const VGrooveMaterial& material, std::span<const double> wavelengths_nm);

struct DirectionalColour {
  Lab lab;
  int max_reflections = 0;
};

// colour_facets: facets_at(material, colour_wavelengths()).
DirectionalColour directional_colour(const VGroove& groove, double theta, double phi, ChainModel model,
                                     std::span<const FacetIndex> colour_facets);

}  // namespace ochre
