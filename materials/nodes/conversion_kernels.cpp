#include "materials/nodes/conversion_kernels.h"

#include "materials/nodes/rgb_upsampling.h"
#include "spectra/memoized_spectrum.h"
#include "spectra/spectrum.h"

namespace ochre {

namespace {

void float_to_colour(const NodeArgs& a) {
  const float x = a.in_float(0);
  a.set_colour(0, {x, x, x});
}
void float_to_vector(const NodeArgs& a) {
  const float x = a.in_float(0);
  a.set_vector(0, {x, x, x});
}
void float_to_spectrum(const NodeArgs& a) {
  a.set_spectrum(0, SampledSpectrum(a.in_float(0)));
}

}  // namespace

NodeFn conversion_kernel(SocketType from, SocketType to, SpectralRole role) {
  if (from == SocketType::kFloat) {
    if (to == SocketType::kColour) return float_to_colour;
    if (to == SocketType::kVector) return float_to_vector;
    if (to == SocketType::kSpectrum) return float_to_spectrum;
  }
  if (from == SocketType::kColour && to == SocketType::kSpectrum) return colour_to_spectrum_kernel(role);
  return nullptr;
}

// Every bounce of a path evaluates its materials at the same wavelengths, and a tabulated spectrum costs an
// interpolation per wavelength and a virtual call: the values are memoized per thread.
void sample_spectrum_kernel(const NodeArgs& a) {
  a.set_spectrum(0, static_cast<const MemoizedSpectrum*>(a.payload)->sample(a.lambda()));
}

}  // namespace ochre
