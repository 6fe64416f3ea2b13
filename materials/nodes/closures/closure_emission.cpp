// emission(color, strength): emitted radiance strength x color (no lobes). With the default
// colour (1,1,1) (illuminant upsampling: D65 with luminance 1) the strength is the luminance.

#include <algorithm>

#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

// Constant inputs are checked >= 0 when the material compiles; a value that varies (a texture, a product
// with one) can still be negative somewhere and counts as 0 there: a light never emits negative radiance.
void emit_emission(const NodeArgs& a) {
  const float strength = std::max(a.in_float(1), 0.0f);
  a.add_emission(clamp_zero(a.weight() * a.in_spectrum(0) * strength));
}

ClosureTraits emission_traits(std::span<const InputView> in, const void*) {
  for (const InputView& v : in)
    if (v.is_constant() && is_zero(*v.value)) return {};
  return {0, true};
}

}  // namespace

NodeDefinition emission_node() {
  NodeDefinition d;
  d.name = "emission";
  d.doc = "Emitted radiance strength x color, added to the closure's emission (no lobes).";
  d.inputs = {
      colour_input("color", SocketType::kSpectrum, {1.0f, 1.0f, 1.0f}, SpectralRole::kIlluminant,
                   clamped_range(0.0f, std::nullopt),
                   "emitted spectral radiance per unit strength; a colour is upsampled as an "
                   "illuminant; negative constants are errors, a negative linked value (e.g. a texel) "
                   "counts as 0"),
      float_input("strength", SocketType::kFloat, 1.0f, clamped_range(0.0f, std::nullopt),
                  "radiance scale; a negative linked value counts as 0")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the emission"}};
  d.eval = emit_emission;
  d.closure_traits = emission_traits;
  return d;
}

}  // namespace ochre
