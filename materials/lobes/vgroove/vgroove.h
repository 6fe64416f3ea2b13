#pragma once
// One cavity of a surface of parallel, identical V-grooves with mirror-like facets (Saint-Pierre,
// Chavel, Simonot and Hebert 2019, Sec 2), in the groove frame: x along the groove, z the mean surface
// normal. The facets have unit width and meet at the apex O = (0, 0); the opening is the segment
// y in [-sin(alpha/2), sin(alpha/2)] at height z = cos(alpha/2). Facet 1 lies on the y < 0 side with
// normal N1 = (0, cos(alpha/2), sin(alpha/2)), facet 2 on the y > 0 side with N2 = (0, -cos(alpha/2),
// sin(alpha/2)) (Eqs 1-2); alpha is the dihedral (opening) angle, pi = a flat surface.
//
// Reflections leave the x component of a direction unchanged, so a ray's path is decided in the (y, z)
// cross-section. There, unfolding the cavity (reflecting it across the facet just hit) turns the path
// into a straight line through the facet images; the images of the opening are chords of the unit
// circle, so the number of reflections follows from where the line leaves the unit circle (Eqs 4-13;
// computed here without the arcsines of Eqs 9 and 11, which lose precision near grazing rays).
// docs/materials/vgroove.md shows the construction.

#include <vector>

#include "materials/core/vec3d.h"
#include "materials/lobes/reflection_chain.h"

namespace ochre {

struct VGroovePath {
  int reflections = 0;  // m (Eq 13)
  int first_facet = 1;  // the facet met first, 1 or 2 (Eq 6)
  Vec3d exit;           // unit direction in which the ray leaves the cavity (pointing away from the surface)
};

class VGroove {
 public:
  // 0 < alpha <= pi (radians).
  explicit VGroove(double alpha);

  double alpha() const { return alpha_; }
  double half_opening() const { return half_opening_; }  // sin(alpha/2): entry positions y_p in [-h, h]
  double depth() const { return depth_; }                // cos(alpha/2): height of the opening above the apex
  const Vec3d& facet_normal(int facet) const { return facet == 1 ? n1_ : n2_; }
  // The most reflections any ray can make: the unfolded line leaves the circle less than pi beyond the
  // opening, so m <= ceil(pi / alpha).
  int max_reflections() const { return max_reflections_; }

  // The path of the ray that enters the cavity through the opening at y = y_p travelling along -e (e is
  // the unit direction towards the viewer or the light, e.z > 0).
  VGroovePath trace(const Vec3d& e, double y_p) const;

  // The entry positions in (-h, h) at which the path seen along -e changes (its reflection count or
  // first facet), sorted, with -h and h added: between two successive values every ray follows the same
  // sequence of facets, so its response is constant there. These are the rays through the apex and
  // through the images of the rim vertices.
  std::vector<double> breakpoints(const Vec3d& e) const;

  // The facet of the j-th reflection (1-based) of a path: facets alternate.
  static int facet_of_reflection(const VGroovePath& path, int j) {
    return (j % 2 == 1) ? path.first_facet : 3 - path.first_facet;
  }

 private:
  double alpha_, half_opening_, depth_;
  Vec3d n1_, n2_;
  int max_reflections_;
};

// Walks a traced path's reflections in the order light meets them (the reverse of the traced order: the
// light arrives along -path.exit and leaves along the viewer's direction), calling on_step(ChainStep)
// for each. Returns the chain's frames (first_s() for the light arriving, last_s() for the light
// leaving).
template <class OnStep>
ChainFrames light_chain(const VGroove& groove, const VGroovePath& path, OnStep&& on_step) {
  return reversed_light_chain(
      path.exit, path.reflections,
      [&](int j) -> const Vec3d& { return groove.facet_normal(VGroove::facet_of_reflection(path, j)); },
      on_step);
}

}  // namespace ochre
