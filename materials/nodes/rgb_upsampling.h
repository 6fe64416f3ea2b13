#pragma once
// RGB -> spectrum at run time, for colours that are not constants (textures, vertex colours):
// one sigmoid-table lookup per evaluation (Jakob & Hanika 2019), with the semantics of
// spectra/rgb_spectrum.h. Constant colours are converted once at compile time instead
// (colour_to_spectrum in node_value.h).

#include "materials/nodes/node_args.h"
#include "materials/nodes/socket_type.h"

namespace ochre {

// Reflectance: RGBAlbedoSpectrum when every component is <= 1, RGBUnboundedSpectrum above (a
// texture may hold albedos above 1 on purpose). Negative components count as 0.
SampledSpectrum upsample_reflectance(const RGB& rgb, const SampledWavelengths& lambda);
// Illuminant: RGBIlluminantSpectrum (unbounded spectrum times D65 at luminance 1).
SampledSpectrum upsample_illuminant(const RGB& rgb, const SampledWavelengths& lambda);

// Instruction converting the colour in[0] to the spectrum out[0] with this role (kNone and
// kInherit are treated as reflectance).
NodeFn colour_to_spectrum_kernel(SpectralRole role);

}  // namespace ochre
