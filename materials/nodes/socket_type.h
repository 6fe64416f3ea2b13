#pragma once
// The value types that flow along the edges of a material graph, and the implicit conversions
// between them (docs/nodes.md, "Types").

#include <cstdint>
#include <optional>

namespace ochre {

enum class SocketType : uint8_t {
  kFloat,
  kColour,    // linear Rec.709 RGB
  kSpectrum,  // a function of wavelength, sampled at the path's 8 wavelengths at run time
  kVector,    // 3D vector (uv coordinates are (u, v, 0))
  kClosure,   // a weighted sum of BSDF lobes plus emission
};

const char* to_string(SocketType type);

// How a colour becomes a spectrum where a spectrum is expected (Jakob & Hanika 2019 upsampling):
// reflectance = smooth bounded spectrum (RGBAlbedoSpectrum; RGBUnboundedSpectrum above 1),
// illuminant = RGBIlluminantSpectrum (white (1,1,1) is D65 with luminance 1).
// kInherit marks a polymorphic math input whose role is the role of the node's own consumers.
enum class SpectralRole : uint8_t { kNone, kReflectance, kIlluminant, kInherit };

const char* to_string(SpectralRole role);

// Conversions done silently when a value of type `from` is connected to a socket of type `to`:
// float -> colour, float -> spectrum, colour -> spectrum (by the socket's role).
bool converts_implicitly(SocketType from, SocketType to);

// Number of floats a value of this type takes in a register frame (closures: their weight).
int register_floats(SocketType type);

}  // namespace ochre
