// chandrasekhar(albedo): Chandrasekhar's BRDF of a half space of isotropic scatterers
// (materials/lobes/chandrasekhar_halfspace.h), the exact H function tabulated once.

#include "materials/lobes/chandrasekhar_halfspace.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

void emit_chandrasekhar(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  a.add_lobe(a.arena.make<ChandrasekharLobe>(a.in_spectrum(0)), w);
}

ClosureTraits chandrasekhar_traits(std::span<const InputView> in, const void*) {
  if (in[0].is_constant() && is_zero(*in[0].value)) return {};
  return {kLobeReflection | kLobeDiffuse, false};
}

}  // namespace

NodeDefinition chandrasekhar_node() {
  NodeDefinition d;
  d.name = "chandrasekhar";
  d.doc =
      "Chandrasekhar's half space of isotropic scatterers: f = c H(mu_i) H(mu_o) / (4 pi (mu_i + mu_o)) "
      "with the exact H function. A depolarizer.";
  d.inputs = {reflectance_input("albedo", 0.8f, clamped_range(0.0f, 1.0f),
                                "single-scattering albedo c of the particles (not the surface's albedo)")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the Chandrasekhar lobe"}};
  d.eval = emit_chandrasekhar;
  d.closure_traits = chandrasekhar_traits;
  return d;
}

}  // namespace ochre
