// lambert(color): the ideal diffuse reflector f = 1/pi with albedo `color`, which becomes the
// lobe's closure weight (as OSL's diffuse(N) scaled by a colour).

#include "materials/lobes/lambert.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

void emit_lambert(const NodeArgs& a) {
  const SampledSpectrum w = a.weight() * a.in_spectrum(0);
  if (w.is_black()) return;
  a.add_lobe(a.arena.make<LambertLobe>(), w);
}

ClosureTraits lambert_traits(std::span<const InputView> in, const void*) {
  if (in[0].is_constant() && is_zero(*in[0].value)) return {};
  return {LambertLobe().flags(), false};
}

}  // namespace

NodeDefinition lambert_node() {
  NodeDefinition d;
  d.name = "lambert";
  d.doc = "Ideal diffuse reflection f = color / pi (a depolarizer).";
  d.inputs = {reflectance_input(
      "color", 0.8f, constant_range(0.0f, std::nullopt),
      "albedo; values above 1 are allowed (not energy conserving), negative constants are errors")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the diffuse lobe"}};
  d.eval = emit_lambert;
  d.closure_traits = lambert_traits;
  return d;
}

}  // namespace ochre
