#include "cli/vgroove_library_values.h"

#include <numbers>
#include <stdexcept>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove_reference.h"
#include "spectra/named_spectra.h"

namespace ochre::test {

namespace {

ChainModel chain_model(const std::string& name) {
  if (name == "rigorous") return ChainModel::kRigorous;
  if (name == "unpolarized") return ChainModel::kUnpolarized;
  if (name == "sp") return ChainModel::kSeparateSP;
  if (name == "paper_literal") return ChainModel::kPaperLiteral;
  throw std::invalid_argument("unknown model " + name);
}

std::vector<FacetIndex> facets(const FacetSpec& f) {
  return {f.mirror ? FacetIndex::ideal_mirror() : FacetIndex::conductor(f.n, f.k)};
}

}  // namespace

FacetSpec tabulated_facet(const std::string& element, double wavelength_nm) {
  const float lambda = static_cast<float>(wavelength_nm);
  return {named_spectrum("metal-" + element + "-eta")->eval(lambda),
          named_spectrum("metal-" + element + "-k")->eval(lambda), false};
}

double library_bihemispherical(const FacetSpec& facet, double alpha_deg, const std::string& model,
                               int reflection_limit) {
  return bihemispherical_reflectance(VGroove(alpha_deg * kDegD), chain_model(model), facets(facet),
                                     reflection_limit)[0];
}

LibraryDirectional library_directional(const FacetSpec& facet, double alpha_deg, double theta_deg,
                                       double phi_deg, const std::string& model) {
  const DirectionalReflectance r = directional_reflectance(
      VGroove(alpha_deg * kDegD), groove_direction(theta_deg * kDegD, phi_deg * kDegD), chain_model(model),
      facets(facet));
  return {r.reflectance[0], r.max_reflections};
}

}  // namespace ochre::test
