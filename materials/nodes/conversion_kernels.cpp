#include "materials/nodes/conversion_kernels.h"

#include "materials/nodes/rgb_upsampling.h"
#include "spectra/spectrum.h"
#include "spectra/wavelength_memo.h"

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

SampledSpectrumPayload::SampledSpectrumPayload(const Spectrum* s)
    : spectrum(s), serial(new_wavelength_memo_key()) {}

// Every bounce of a path evaluates its materials at the same wavelengths, and a tabulated spectrum costs an
// interpolation per wavelength and a virtual call: the values are memoized per thread
// (spectra/wavelength_memo.h).
void sample_spectrum_kernel(const NodeArgs& a) {
  const auto& payload = *static_cast<const SampledSpectrumPayload*>(a.payload);
  a.set_spectrum(
      0, memo_sampled(payload.serial, a.lambda(), [&] { return payload.spectrum->sample(a.lambda()); }));
}

}  // namespace ochre
