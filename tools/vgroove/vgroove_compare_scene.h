#pragma once
// The scenes of `ochre-vgroove compare` (docs/tools.md): one V-groove surface under a constant white
// environment, seen from (theta, phi) by an orthographic camera, so that the mean of the image relative
// to the environment alone is the surface's hemispherical-directional reflectance R(theta, phi)
// (Saint-Pierre et al. 2019, Eq 36). Three descriptions of the same surface:
//   kExplicit     a `groove_plate` of real triangles with a smooth conductor (or ideal mirror) material;
//   kAnalytic     a `plane` with the `vgroove` material;
//   kMicrogroove  a `plane` with the `microgroove` material (profile v).
// The grooves run along x (the plane's dp/du), phi is measured from y, as in vgroove_reference.h.
//
// The image mean is R exactly (in expectation), not only for fine grooves: the pitch puts one groove
// period in each pixel along the image axis that crosses the grooves fastest (the image of a plate is
// periodic across the grooves), and the plate reaches beyond the frame's footprint.

#include <string>

#include "materials/lobes/reflection_chain.h"

namespace ochre {

enum class GrooveSurface { kExplicit, kAnalytic, kMicrogroove };

struct CompareView {
  double alpha_deg = 45;  // dihedral angle, [1, 179.9]
  double theta_deg = 0;   // view direction, [0, 85]
  double phi_deg = 0;     // from the axis across the grooves
  FacetIndex facet;       // the facets' constant index (or an ideal mirror)
  int resolution = 64;    // square film
  int spp = 64;
  int threads = 0;  // 0 = all cores
  unsigned long long seed = 0;
};

// max_depth (= rr_depth, no Russian roulette): the longest path in the groove, ceil(180 / alpha)
// reflections, and 2 to spare.
int compare_max_depth(double alpha_deg);

// The scene text.
std::string compare_scene_json(GrooveSurface surface, const CompareView& view);
// The environment alone, with the film, samples and seed of `view`: the same wavelengths per sample.
std::string environment_scene_json(const CompareView& view);

}  // namespace ochre
