// oren_nayar(color, sigma): Oren-Nayar rough diffuse reflection, the qualitative 1994 model
// (materials/lobes/oren_nayar.h), albedo `color` as the closure weight.

#include "materials/lobes/oren_nayar.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

void emit_oren_nayar(const NodeArgs& a) {
  const SampledSpectrum w = a.weight() * a.in_spectrum(0);
  if (w.is_black()) return;
  a.add_lobe(a.arena.make<OrenNayarLobe>(std::max(0.0f, a.in_float(1))), w);
}

ClosureTraits oren_nayar_traits(std::span<const InputView> in, const void*) {
  if (in[0].is_constant() && is_zero(*in[0].value)) return {};
  return {kLobeReflection | kLobeDiffuse, false};
}

}  // namespace

NodeDefinition oren_nayar_node() {
  NodeDefinition d;
  d.name = "oren_nayar";
  d.doc = "Oren-Nayar rough diffuse reflection (the qualitative 1994 model), albedo `color`. A depolarizer.";
  d.inputs = {reflectance_input("color", 0.8f, constant_range(0.0f, std::nullopt),
                                "albedo (the closure weight, as for lambert)"),
              float_input("sigma", SocketType::kFloat, 0.3f, constant_range(0.0f, std::nullopt),
                          "roughness: standard deviation of the facet slope angle, radians (0 = Lambert)")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the Oren-Nayar lobe"}};
  d.eval = emit_oren_nayar;
  d.closure_traits = oren_nayar_traits;
  return d;
}

}  // namespace ochre
