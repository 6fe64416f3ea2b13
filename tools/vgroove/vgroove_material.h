#pragma once
// The facet material of ochre-vgroove (docs/tools.md): a name or an explicit complex index.
//   Au, Ag, Cu, Al, Si   the renderer's optical constants (named spectra metal-X-eta / metal-X-k)
//   glass                black glass of Saint-Pierre et al. 2019: n = 1.5 at every wavelength
//   paper-silver         the silver of the paper's Tables 1 and 3: n = 0.1249 + 3.3391i (their value at
//                        550 nm; no dataset gives it), used at every wavelength
//   mirror               ideal mirror facets (reflectance 1)
//   --ior n,k            the index n + i k at every wavelength (k >= 0)
// Names are matched without regard to case.

#include <string>
#include <string_view>
#include <vector>

#include "materials/lobes/reflection_chain.h"
#include "spectra/spectrum.h"

namespace ochre {

class VGrooveMaterial {
 public:
  // Exactly one of name and ior must be non-empty; throws InputError naming --material or --ior.
  static VGrooveMaterial parse(std::string_view name, std::string_view ior);
  static VGrooveMaterial named(std::string_view name) { return parse(name, ""); }
  // --material as a comma list of names, or the one --ior.
  static std::vector<VGrooveMaterial> parse_list(std::string_view names, std::string_view ior);

  // The CSV label: the canonical name ("Au", "glass", ...) or "n=N k=K" for --ior.
  const std::string& label() const { return label_; }
  FacetIndex at(double wavelength_nm) const;

 private:
  std::string label_;
  FacetIndex constant_;
  SpectrumPtr eta_, k_;  // set for tabulated materials
};

}  // namespace ochre
