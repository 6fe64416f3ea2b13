// dielectric(ior, roughness; opaque): a dielectric interface with a wavelength-independent index,
// polarizing (materials/lobes/dielectric.h). roughness 0: smooth (delta) reflection and refraction, or
// reflection only with opaque = 1 (black glass: the refracted part is absorbed). roughness > 0: GGX
// reflection only; the refracted part is not traced (lost).

#include <algorithm>
#include <memory>

#include "materials/lobes/dielectric.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_definition.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

struct DielectricOptions {
  bool opaque = false;
};

Prepared prepare_dielectric(const PrepareArgs& args) {
  Prepared p;
  DielectricOptions options;
  options.opaque = args.params.contains("opaque") && args.params.at("opaque").get<int>() != 0;
  p.payload = std::make_shared<DielectricOptions>(options);
  return p;
}

constexpr float kMinIor = 0.01f;

void emit_dielectric(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  const float eta = std::max(a.in_float(0), kMinIor);
  const float alpha = nan_safe_clamp(a.in_float(1), 0.0f, 1.0f);
  if (alpha > 0.0f)
    a.add_lobe(a.arena.make<RoughDielectricLobe>(eta, alpha), w);
  else
    a.add_lobe(a.arena.make<SmoothDielectricLobe>(eta, a.data<DielectricOptions>().opaque), w);
}

ClosureTraits dielectric_traits(std::span<const InputView> in, const void*) {
  // The traits cannot see the `opaque` parameter: transmission is declared whenever a smooth lobe
  // may be made (a superset of the flags, which is what the facts need).
  const uint32_t base = kLobeReflection | kLobePolarizing;
  const uint32_t smooth = kLobeDelta | kLobeTransmission, rough = kLobeGlossy;
  if (!in[1].is_constant()) return {base | smooth | rough, false};
  return {base | (in[1].value->f > 0.0f ? rough : smooth), false};
}

}  // namespace

NodeDefinition dielectric_node() {
  NodeDefinition d;
  d.name = "dielectric";
  d.doc = "A dielectric interface (glass, water, black glass) with a constant index; polarizing.";
  d.inputs = {float_input("ior", SocketType::kFloat, 1.5f, clamped_range(kMinIor, std::nullopt),
                          "relative index n_inside / n_outside (the normal points outside); linked values "
                          "below 0.01 are raised to it"),
              float_input("roughness", SocketType::kFloat, 0.0f, clamped_range(0.0f, 1.0f),
                          "GGX alpha (not squared); 0 = smooth (delta); > 0: rough reflection only")};
  d.params = {integer_param(
      "opaque", 0, 0, 1, "1: the refracted part is absorbed (black glass), 0: it is traced (smooth only)")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the dielectric lobe"}};
  d.prepare = prepare_dielectric;
  d.eval = emit_dielectric;
  d.closure_traits = dielectric_traits;
  return d;
}

}  // namespace ochre
