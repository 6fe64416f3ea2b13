#include "tools/vgroove/vgroove_spectral.h"

#include "tools/vgroove/vgroove_colour.h"

namespace ochre {

std::vector<FacetIndex> facets_at(const VGrooveMaterial& material, std::span<const double> wavelengths_nm) {
  std::vector<FacetIndex> facets;
  facets.reserve(wavelengths_nm.size());
  for (double lambda : wavelengths_nm) facets.push_back(material.at(lambda));
  return facets;
}

DirectionalColour directional_colour(const VGroove& groove, double theta, double phi, ChainModel model,
                                     std::span<const FacetIndex> colour_facets) {
  const DirectionalReflectance r =
      directional_reflectance(groove, groove_direction(theta, phi), model, colour_facets);
  return {reflectance_to_lab(r.reflectance), r.max_reflections};
}

}  // namespace ochre
