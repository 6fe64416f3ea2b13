#pragma once
// Registry of spectra known by name (scene files refer to them as strings).
//
//   named_spectrum("D65" | "A" | "E" | "cie_x" | "cie_y" | "cie_z") -> SpectrumPtr
//       Illuminants (D65, A, E = equal energy) have luminance 1 (see cie.h); cie_* are the CIE 1931
//       colour matching functions. Unknown names throw std::invalid_argument listing the known ones.
//   named_spectrum("LED-4100K-model") -> a model white LED (docs/lights.md), luminance 1.
//   named_spectrum("metal-Au-eta" | "metal-Au-k" | ... Ag, Cu, Al, Si) -> optical constants n and k
//       (index n + i k as tabulated, 300-900 nm, held constant beyond) from spectra/data/ior_*_5nm.csv.
//   list_named_spectra() -> the known names, in registry order.
// Adding a spectrum is one line in the registry in named_spectra.cpp.

#include <string_view>
#include <vector>

#include "spectra/spectrum.h"

namespace ochre {

SpectrumPtr named_spectrum(std::string_view name);
std::vector<std::string_view> list_named_spectra();

}  // namespace ochre
