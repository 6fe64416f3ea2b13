#pragma once
// The V-groove library's own values (materials/lobes/vgroove/), for checking ochre-vgroove's output,
// behind plain types so the tool tests need no model headers.

#include <string>
#include <vector>

namespace ochre::test {

struct FacetSpec {
  double n = 1.5, k = 0.0;
  bool mirror = false;
};

// The renderer's optical constants of "Au", "Ag", "Cu", "Al" or "Si" at one wavelength.
FacetSpec tabulated_facet(const std::string& element, double wavelength_nm);

// model: "rigorous", "unpolarized", "sp" or "paper_literal".
double library_bihemispherical(const FacetSpec& facet, double alpha_deg, const std::string& model,
                               int reflection_limit = 0);

struct LibraryDirectional {
  double reflectance;
  int max_reflections;
};
LibraryDirectional library_directional(const FacetSpec& facet, double alpha_deg, double theta_deg,
                                       double phi_deg, const std::string& model);

}  // namespace ochre::test
