// mix(a, b, factor): (1 - f) a + f b with f = factor clamped to [0, 1]. For closures, the weights
// of a and b are scaled by (1 - f) and f (OSL closure mix).

#include <algorithm>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/math_node_types.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

float clamped_factor(const NodeArgs& a) {
  return nan_safe_clamp(a.in_float(2), 0.0f, 1.0f);
}

void mix_float(const NodeArgs& a) {
  const float f = clamped_factor(a);
  a.set_float(0, (1.0f - f) * a.in_float(0) + f * a.in_float(1));
}

void mix_colour(const NodeArgs& a) {
  const float f = clamped_factor(a), g = 1.0f - f;
  const RGB x = a.in_colour(0), y = a.in_colour(1);
  a.set_colour(0, {g * x.r + f * y.r, g * x.g + f * y.g, g * x.b + f * y.b});
}

void mix_vector(const NodeArgs& a) {
  const float f = clamped_factor(a);
  a.set_vector(0, (1.0f - f) * a.in_vector(0) + f * a.in_vector(1));
}

void mix_spectrum(const NodeArgs& a) {
  const float f = clamped_factor(a);
  a.set_spectrum(0, (1.0f - f) * a.in_spectrum(0) + f * a.in_spectrum(1));
}

void mix_closures(const NodeArgs& a) {
  const float f = clamped_factor(a);
  const SampledSpectrum w = a.weight();
  a.add_weight(0, w * (1.0f - f));
  a.add_weight(1, w * f);
}

TypeResolution resolve_mix(std::span<const SocketType> connected) {
  const SocketType t = combine_operands(connected[0], connected[1], "mix");
  return {{t, t, SocketType::kFloat}, {t}};
}

NodeFn select_mix(const TypeResolution& types) {
  switch (types.outputs[0]) {
    case SocketType::kFloat:
      return mix_float;
    case SocketType::kColour:
      return mix_colour;
    case SocketType::kVector:
      return mix_vector;
    case SocketType::kSpectrum:
      return mix_spectrum;
    case SocketType::kClosure:
      return mix_closures;
  }
  return nullptr;
}

// A constant factor of 0 or 1 selects one operand; the other becomes dead.
FoldResult fold_mix(const FoldArgs& args) {
  const std::span<const InputView> in = args.inputs;
  FoldResult r;
  if (!in[2].is_constant()) return r;
  const float f = in[2].value->f;
  if (f == 0.0f || f == 1.0f) {
    r.kind = FoldResult::Kind::kForward;
    r.forward_input = f == 0.0f ? 0 : 1;
  }
  return r;
}

}  // namespace

NodeDefinition mix_node() {
  NodeDefinition d;
  d.name = "mix";
  d.doc =
      "Linear blend (1 - factor) a + factor b. Values: the promoted type of a and b. Closures: both weighted "
      "sums, scaled by (1 - factor) and factor (OSL closure mix).";
  d.inputs = {operand_input("a", 0.0f, "value or closure at factor 0"),
              operand_input("b", 0.0f, "value or closure at factor 1"),
              float_input("factor", SocketType::kFloat, 0.5f, clamped_range(0.0f, 1.0f),
                          "blend factor; a constant must lie in [0, 1], a linked value is clamped to it")};
  d.outputs = {{"result", SocketType::kFloat, true, "the blend"}};
  d.resolve_types = resolve_mix;
  d.select = select_mix;
  d.fold = fold_mix;
  return d;
}

}  // namespace ochre
