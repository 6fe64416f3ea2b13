#include "materials/nodes/socket_type.h"

#include "spectra/sampled_spectrum.h"

namespace ochre {

const char* to_string(SocketType type) {
  switch (type) {
    case SocketType::kFloat:
      return "float";
    case SocketType::kColour:
      return "colour";
    case SocketType::kSpectrum:
      return "spectrum";
    case SocketType::kVector:
      return "vector";
    case SocketType::kClosure:
      return "closure";
  }
  return "?";
}

const char* to_string(SpectralRole role) {
  switch (role) {
    case SpectralRole::kNone:
      return "none";
    case SpectralRole::kReflectance:
      return "reflectance";
    case SpectralRole::kIlluminant:
      return "illuminant";
    case SpectralRole::kInherit:
      return "inherit";
  }
  return "?";
}

bool converts_implicitly(SocketType from, SocketType to) {
  if (from == to) return true;
  if (from == SocketType::kFloat) return to == SocketType::kColour || to == SocketType::kSpectrum;
  return from == SocketType::kColour && to == SocketType::kSpectrum;
}

int register_floats(SocketType type) {
  switch (type) {
    case SocketType::kFloat:
      return 1;
    case SocketType::kColour:
    case SocketType::kVector:
      return 3;
    case SocketType::kSpectrum:
    case SocketType::kClosure:
      return kSpectrumSamples;
  }
  return 0;
}

}  // namespace ochre
