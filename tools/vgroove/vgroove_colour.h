#pragma once
// The colorimetry of Saint-Pierre et al. 2019 (Sec 4.2): spectral reflectances at 380-730 nm in 10 nm
// steps are converted to CIE 1931 XYZ (2 degree observer) under illuminant D65, then to CIE 1976
// L*a*b* with the perfect white diffuser under D65 as the reference white, then to sRGB for display.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "spectra/ciede2000.h"

namespace ochre {

// 380, 390, ..., 730 nm (36 wavelengths).
const std::vector<double>& colour_wavelengths();

// L*a*b* of a reflectance spectrum given at colour_wavelengths(); a perfect white diffuser (all 1) gives
// L* = 100, a* = b* = 0.
Lab reflectance_to_lab(std::span<const double> reflectance);

// 8-bit sRGB of a colour: L*a*b* back to XYZ relative to the sRGB white (D65), the sRGB primaries,
// clipping to [0, 1] and the sRGB transfer function. The white diffuser gives (255, 255, 255).
std::array<std::uint8_t, 3> lab_to_srgb8(const Lab& lab);

}  // namespace ochre
