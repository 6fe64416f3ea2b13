#pragma once
// NodeValue: a constant on a graph edge (a literal in the scene, a pre-built spectrum, or the
// result of constant folding), and the compile-time conversions between constant types.

#include <string>

#include "materials/core/vec3.h"
#include "materials/nodes/socket_type.h"
#include "spectra/color_types.h"
#include "spectra/spectrum.h"

namespace ochre {

struct NodeValue {
  SocketType type = SocketType::kFloat;
  float f = 0.0f;
  RGB colour;
  Vec3 vector;
  SpectrumPtr spectrum;  // never null when type == kSpectrum

  static NodeValue of_float(float v);
  static NodeValue of_colour(const RGB& c);
  static NodeValue of_vector(const Vec3& v);
  static NodeValue of_spectrum(SpectrumPtr s);

  // Short text for messages and listings: 0.5, [0.1, 0.2, 0.3], {vector: ...}, spectrum(...).
  std::string describe() const;
};

// True when every float of the value is finite (spectra are checked at 1 nm steps).
bool is_finite(const NodeValue& v);
// Smallest float of the value (spectra: over 360-830 nm at 1 nm steps).
float min_component(const NodeValue& v);
// Largest float of the value (spectra: their max_value()).
float max_component(const NodeValue& v);
// True when the value is exactly zero everywhere.
bool is_zero(const NodeValue& v);

// The spectrum a constant colour stands for in a socket of the given role (pre-built once, so no
// sigmoid lookup happens per evaluation). Greys with the reflectance role become ConstantSpectrum
// (exactly r at every wavelength); kNone and kInherit are treated as reflectance.
SpectrumPtr colour_to_spectrum(const RGB& c, SpectralRole role);

// Converts a constant to `to`: any implicit conversion, plus float -> vector (the broadcast math
// nodes use). Precondition: the conversion is one of those.
NodeValue convert_constant(const NodeValue& v, SocketType to, SpectralRole role);

}  // namespace ochre
