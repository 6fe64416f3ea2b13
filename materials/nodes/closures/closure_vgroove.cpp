// vgroove(alpha, eta, k, angle, direction; metal, model, max_reflections, direction_space): a surface
// of parallel specular V-grooves as an analytic delta BSDF (materials/lobes/vgroove/vgroove_lobe.h,
// Saint-Pierre et al. 2019). The groove axis: groove_closure.h.

#include <algorithm>
#include <memory>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove_lobe.h"
#include "materials/nodes/closures/groove_closure.h"
#include "materials/nodes/definition_builders.h"

namespace ochre {

namespace {

constexpr float kMinAlphaDegrees = 0.1f;            // a ray can need 1800 reflections there
constexpr GrooveInputs kVGrooveInputs{1, 2, 3, 4};  // after alpha

Prepared prepare_vgroove(const PrepareArgs& args) {
  Prepared p;
  p.payload = std::make_shared<GrooveFacetSettings>(parse_groove_settings(args));
  return p;
}

void emit_vgroove(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  const GrooveFacetSettings& s = a.data<GrooveFacetSettings>();
  const Vec3 axis = groove_local_axis(a, s, kVGrooveInputs);
  const float alpha_degrees = std::clamp(a.in_float(0), kMinAlphaDegrees, 180.0f);
  a.add_lobe(a.arena.make<VGrooveLobe>(alpha_degrees * kDegD, axis, groove_facet(a, s, kVGrooveInputs),
                                       s.model, s.reflection_limit),
             w);
}

ClosureTraits vgroove_traits(std::span<const InputView>, const void* payload) {
  return groove_traits(*static_cast<const GrooveFacetSettings*>(payload));
}

}  // namespace

NodeDefinition vgroove_node() {
  NodeDefinition d;
  d.name = "vgroove";
  d.doc =
      "Parallel V-grooves with specular facets (Saint-Pierre et al. 2019): a delta BSDF whose rays "
      "reflect 1, 2, ... times inside a groove, traced exactly; polarizing in the rigorous and sp models.";
  d.inputs = {float_input("alpha", SocketType::kFloat, 90.0f, clamped_range(kMinAlphaDegrees, 180.0f),
                          "dihedral (opening) angle of the grooves in degrees; 180 = flat; a linked value "
                          "is clamped to [0.1, 180]")};
  for (SocketDef& s : groove_facet_and_direction_inputs()) d.inputs.push_back(std::move(s));
  d.params = groove_common_params();
  d.outputs = {{"closure", SocketType::kClosure, false, "the V-groove lobe"}};
  d.prepare = prepare_vgroove;
  d.eval = emit_vgroove;
  d.closure_traits = vgroove_traits;
  d.context_usage = kUsesGeometry;
  return d;
}

}  // namespace ochre
