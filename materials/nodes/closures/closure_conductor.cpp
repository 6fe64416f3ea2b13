// conductor(eta, k, roughness; metal): Fresnel reflection off a metal with the complex index n - i k
// per wavelength (materials/lobes/conductor.h), polarizing. roughness 0 is a perfect mirror (delta lobe);
// above 0 it is the GGX alpha of a rough conductor. `metal` names built-in optical constants
// ("Au", "Ag", "Cu", "Al", "Si": the named spectra metal-X-eta / metal-X-k) and then replaces the
// eta and k inputs.

#include <algorithm>
#include <memory>
#include <string>

#include "materials/lobes/conductor.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"
#include "spectra/named_spectra.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

struct NamedMetal {
  SpectrumPtr eta, k;
};

Prepared prepare_conductor(const PrepareArgs& args) {
  Prepared p;
  const std::optional<std::string> metal = choice_name(args, "metal");
  if (!metal) return p;
  p.payload = std::make_shared<NamedMetal>(
      NamedMetal{named_spectrum("metal-" + *metal + "-eta"), named_spectrum("metal-" + *metal + "-k")});
  return p;
}

void emit_conductor(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  SampledSpectrum eta = a.in_spectrum(0), k = a.in_spectrum(1);
  if (a.payload) {
    const NamedMetal& metal = a.data<NamedMetal>();
    eta = metal.eta->sample(a.lambda());
    k = metal.k->sample(a.lambda());
  }
  const float alpha = nan_safe_clamp(a.in_float(2), 0.0f, 1.0f);
  if (alpha > 0.0f)
    a.add_lobe(a.arena.make<RoughConductorLobe>(eta, k, alpha), w);
  else
    a.add_lobe(a.arena.make<SmoothConductorLobe>(eta, k), w);
}

ClosureTraits conductor_traits(std::span<const InputView> in, const void*) {
  const uint32_t base = kLobeReflection | kLobePolarizing;
  if (!in[2].is_constant()) return {base | kLobeDelta | kLobeGlossy, false};
  return {base | (in[2].value->f > 0.0f ? kLobeGlossy : kLobeDelta), false};
}

}  // namespace

NodeDefinition conductor_node() {
  NodeDefinition d;
  d.name = "conductor";
  d.doc = "Fresnel reflection off a metal (complex index n - i k), smooth or GGX-rough; polarizing.";
  d.inputs = {named_spectrum_input("eta", "metal-Cu-eta", "real part n of the index (default: copper)"),
              named_spectrum_input("k", "metal-Cu-k", "extinction coefficient k >= 0 (default: copper)"),
              float_input("roughness", SocketType::kFloat, 0.0f, clamped_range(0.0f, 1.0f),
                          "GGX alpha (not squared); 0 = perfect mirror (delta lobe); a linked value is "
                          "clamped to [0, 1]")};
  d.params = {optional_choice_param("metal", {"Au", "Ag", "Cu", "Al", "Si"},
                                    "built-in optical constants; when given, eta and k are ignored")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the conductor lobe"}};
  d.prepare = prepare_conductor;
  d.eval = emit_conductor;
  d.closure_traits = conductor_traits;
  return d;
}

}  // namespace ochre
