#pragma once
// Run-time kernels of the element-wise math nodes, one per value type, from a scalar operation
// `Op::apply(float, float)` (a struct, so that each instantiation is a plain function pointer).

#include "materials/nodes/node_args.h"
#include "materials/nodes/socket_type.h"

namespace ochre {

template <class Op>
NodeFn binary_kernel(SocketType type) {
  switch (type) {
    case SocketType::kFloat:
      return [](const NodeArgs& a) { a.set_float(0, Op::apply(a.in_float(0), a.in_float(1))); };
    case SocketType::kColour:
      return [](const NodeArgs& a) {
        const RGB x = a.in_colour(0), y = a.in_colour(1);
        a.set_colour(0, {Op::apply(x.r, y.r), Op::apply(x.g, y.g), Op::apply(x.b, y.b)});
      };
    case SocketType::kVector:
      return [](const NodeArgs& a) {
        const Vec3 x = a.in_vector(0), y = a.in_vector(1);
        a.set_vector(0, {Op::apply(x.x, y.x), Op::apply(x.y, y.y), Op::apply(x.z, y.z)});
      };
    case SocketType::kSpectrum:
      return [](const NodeArgs& a) {
        const SampledSpectrum x = a.in_spectrum(0), y = a.in_spectrum(1);
        SampledSpectrum r;
        for (int k = 0; k < kSpectrumSamples; ++k) r[k] = Op::apply(x[k], y[k]);
        a.set_spectrum(0, r);
      };
    case SocketType::kClosure:
      break;
  }
  return nullptr;
}

}  // namespace ochre
