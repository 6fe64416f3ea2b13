#include "tools/vgroove/vgroove_profile.h"

#include <tbb/parallel_for.h>

#include "materials/core/pi.h"
#include "tools/vgroove/vgroove_colour.h"
#include "tools/vgroove/vgroove_spectral.h"

namespace ochre {

std::vector<ProfilePoint> lightness_profiles(const VGrooveMaterial& material, double alpha_deg,
                                             const std::vector<ChainModel>& models, double theta_step_deg) {
  const VGroove groove(alpha_deg * kDegD);
  const std::vector<FacetIndex> facets = facets_at(material, colour_wavelengths());
  std::vector<double> thetas;
  for (int i = 0; i * theta_step_deg < 90.0; ++i) thetas.push_back(i * theta_step_deg);
  std::vector<ProfilePoint> points;
  for (double phi : {0.0, 90.0})
    for (ChainModel model : models)
      for (double theta : thetas) points.push_back({phi, theta, model, 0.0});
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t i) {
    ProfilePoint& p = points[i];
    p.lightness = directional_colour(groove, p.theta_deg * kDegD, p.phi_deg * kDegD, p.model, facets).lab.L;
  });
  return points;
}

}  // namespace ochre
