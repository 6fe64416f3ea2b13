#include "materials/graph/frame_layout.h"

#include <memory>

#include "spectra/constant_spectrum.h"

namespace ochre {

void store_constant(std::vector<float>& frame, uint16_t at, const NodeValue& v) {
  switch (v.type) {
    case SocketType::kFloat:
      frame[at] = v.f;
      break;
    case SocketType::kColour:
      frame[at] = v.colour.r;
      frame[at + 1] = v.colour.g;
      frame[at + 2] = v.colour.b;
      break;
    case SocketType::kVector:
      frame[at] = v.vector.x;
      frame[at + 1] = v.vector.y;
      frame[at + 2] = v.vector.z;
      break;
    case SocketType::kSpectrum: {
      const float x = v.spectrum->eval(550.0f);
      for (int k = 0; k < kSpectrumSamples; ++k) frame[at + k] = x;
      break;
    }
    case SocketType::kClosure:
      break;
  }
}

NodeValue load_constant(const std::vector<float>& frame, uint16_t at, SocketType type) {
  switch (type) {
    case SocketType::kFloat:
      return NodeValue::of_float(frame[at]);
    case SocketType::kColour:
      return NodeValue::of_colour({frame[at], frame[at + 1], frame[at + 2]});
    case SocketType::kVector:
      return NodeValue::of_vector({frame[at], frame[at + 1], frame[at + 2]});
    case SocketType::kSpectrum:
      return NodeValue::of_spectrum(std::make_shared<ConstantSpectrum>(frame[at]));
    case SocketType::kClosure:
      break;
  }
  return {};
}

}  // namespace ochre
