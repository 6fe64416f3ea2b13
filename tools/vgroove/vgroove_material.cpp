#include "tools/vgroove/vgroove_material.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "spectra/input_error.h"
#include "spectra/named_spectra.h"
#include "tools/vgroove/vgroove_inputs.h"

namespace ochre {

namespace {

constexpr std::string_view kTabulated[] = {"Au", "Ag", "Cu", "Al", "Si"};
constexpr std::string_view kKnown = "Au, Ag, Cu, Al, Si, glass, paper-silver, mirror";

bool same_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

VGrooveMaterial VGrooveMaterial::parse(std::string_view name, std::string_view ior) {
  if (name.empty() == ior.empty())
    throw InputError(name.empty() ? "give the facet material: --material NAME or --ior n,k"
                                  : "--material and --ior: give only one of them");
  VGrooveMaterial m;
  if (!ior.empty()) {
    const std::vector<double> nk = parse_number_list("--ior", ior);
    if (nk.size() != 2) throw InputError(fmt::format("--ior: '{}' is not n,k (two numbers)", ior));
    if (!(nk[0] > 0.0)) throw InputError(fmt::format("--ior: n = {} must be positive", nk[0]));
    if (!(nk[1] >= 0.0)) throw InputError(fmt::format("--ior: k = {} must be 0 or more", nk[1]));
    m.label_ = fmt::format("n={} k={}", nk[0], nk[1]);
    m.constant_ = FacetIndex::conductor(nk[0], nk[1]);
    return m;
  }
  for (std::string_view t : kTabulated)
    if (same_ignoring_case(name, t)) {
      m.label_ = std::string(t);
      m.eta_ = named_spectrum(fmt::format("metal-{}-eta", t));
      m.k_ = named_spectrum(fmt::format("metal-{}-k", t));
      return m;
    }
  if (same_ignoring_case(name, "glass")) {
    m.label_ = "glass";
    m.constant_ = FacetIndex::conductor(1.5, 0.0);
  } else if (same_ignoring_case(name, "paper-silver")) {
    m.label_ = "paper-silver";
    m.constant_ = FacetIndex::conductor(0.1249, 3.3391);
  } else if (same_ignoring_case(name, "mirror")) {
    m.label_ = "mirror";
    m.constant_ = FacetIndex::ideal_mirror();
  } else {
    throw InputError(
        fmt::format("--material: unknown material '{}' (known: {}; or --ior n,k)", name, kKnown));
  }
  return m;
}

std::vector<VGrooveMaterial> VGrooveMaterial::parse_list(std::string_view names, std::string_view ior) {
  if (!ior.empty() || names.empty()) return {parse(names, ior)};
  std::vector<VGrooveMaterial> materials;
  for (std::string_view name : split_list("--material", names)) materials.push_back(named(name));
  return materials;
}

FacetIndex VGrooveMaterial::at(double wavelength_nm) const {
  if (!eta_) return constant_;
  const float lambda = static_cast<float>(wavelength_nm);
  return FacetIndex::conductor(eta_->eval(lambda), k_->eval(lambda));
}

}  // namespace ochre
