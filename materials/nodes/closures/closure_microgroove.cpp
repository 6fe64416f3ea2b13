// microgroove(eta, k, angle, direction; profile, alpha, slope1, slope2, bottom, segments, alpha_min,
// alpha_max, metal, model, max_reflections, direction_space): parallel grooves described by explicit
// microgeometry, a periodic cross-section traced facet by facet (materials/lobes/vgroove/
// microgroove_lobe.h). The groove axis: groove_closure.h.

#include <array>
#include <memory>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/microgroove_lobe.h"
#include "materials/nodes/closures/groove_closure.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"

namespace ochre {

namespace {

constexpr GrooveInputs kMicrogrooveInputs{0, 1, 2, 3};

enum class ProfileShape { kV, kAsymmetricV, kFlatBottom, kRounded, kVMix };
constexpr std::array kProfileShapes{
    Choice{"v", ProfileShape::kV}, Choice{"asymmetric_v", ProfileShape::kAsymmetricV},
    Choice{"flat_bottom", ProfileShape::kFlatBottom}, Choice{"rounded", ProfileShape::kRounded},
    Choice{"v_mix", ProfileShape::kVMix}};

struct MicrogrooveSettings {
  GrooveFacetSettings facet;
  std::shared_ptr<const GrooveProfile> profile;  // null for the V mix
  double alpha_min = 0.0, alpha_max = 0.0;       // radians
};

double degrees_param(const PrepareArgs& args, const char* name, double fallback) {
  return (args.params.contains(name) ? args.params.at(name).get<double>() : fallback) * kDegD;
}

Prepared prepare_microgroove(const PrepareArgs& args) {
  auto s = std::make_shared<MicrogrooveSettings>();
  s->facet = parse_groove_settings(args);
  const double alpha = degrees_param(args, "alpha", 90.0);
  switch (choice_value(args, "profile", kProfileShapes)) {
    case ProfileShape::kV:
      s->profile = std::make_shared<GrooveProfile>(GrooveProfile::v(alpha));
      break;
    case ProfileShape::kAsymmetricV: {
      const double slope1 = degrees_param(args, "slope1", 45.0), slope2 = degrees_param(args, "slope2", 45.0);
      s->profile = std::make_shared<GrooveProfile>(GrooveProfile::asymmetric_v(slope1, slope2));
      break;
    }
    case ProfileShape::kFlatBottom: {
      const double bottom = args.params.contains("bottom") ? args.params.at("bottom").get<double>() : 0.3;
      s->profile = std::make_shared<GrooveProfile>(GrooveProfile::flat_bottom(alpha, bottom));
      break;
    }
    case ProfileShape::kRounded: {
      const int segments = args.params.contains("segments") ? args.params.at("segments").get<int>() : 32;
      s->profile = std::make_shared<GrooveProfile>(GrooveProfile::rounded(alpha, segments));
      break;
    }
    case ProfileShape::kVMix:
      s->alpha_min = degrees_param(args, "alpha_min", 45.0);
      s->alpha_max = degrees_param(args, "alpha_max", 90.0);
      if (s->alpha_max < s->alpha_min) throw NodeError("alpha_max", "must not be less than alpha_min");
      break;
  }
  Prepared p;
  p.payload = s;
  return p;
}

void emit_microgroove(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  const MicrogrooveSettings& s = a.data<MicrogrooveSettings>();
  const Vec3 axis = groove_local_axis(a, s.facet, kMicrogrooveInputs);
  const MicrogrooveShape shape{s.profile.get(), s.alpha_min, s.alpha_max};
  a.add_lobe(a.arena.make<MicrogrooveLobe>(shape, axis, groove_facet(a, s.facet, kMicrogrooveInputs),
                                           s.facet.model, s.facet.reflection_limit),
             w);
}

ClosureTraits microgroove_traits(std::span<const InputView>, const void* payload) {
  return groove_traits(static_cast<const MicrogrooveSettings*>(payload)->facet);
}

}  // namespace

NodeDefinition microgroove_node() {
  NodeDefinition d;
  d.name = "microgroove";
  d.doc =
      "Parallel grooves described by explicit microgeometry: a periodic profile (V, asymmetric V, flat "
      "bottom, rounded, or a mix of V angles) traced facet by facet with a Fresnel reflection at each; a "
      "delta BSDF, polarizing in the rigorous and sp models.";
  d.inputs = groove_facet_and_direction_inputs();
  d.params = {
      choice_param("profile", "v", choice_names(kProfileShapes), "cross-section of one groove"),
      number_param("alpha", 90.0, 1.0, 179.9,
                   "v, flat_bottom, rounded: dihedral angle in degrees (rounded: between the rim "
                   "tangents)"),
      number_param("slope1", 45.0, 1.0, 89.0, "asymmetric_v: slope of the left facet in degrees"),
      number_param("slope2", 45.0, 1.0, 89.0, "asymmetric_v: slope of the right facet in degrees"),
      number_param("bottom", 0.3, 0.0, 0.99, "flat_bottom: the fraction of the V's depth cut flat"),
      integer_param("segments", 32, 2, GrooveProfile::kMaxSegments, "rounded: chords approximating the arc"),
      number_param("alpha_min", 45.0, 1.0, 179.9, "v_mix: smallest dihedral angle in degrees"),
      number_param("alpha_max", 90.0, 1.0, 179.9,
                   "v_mix: largest dihedral angle in degrees (grooves of equal width, angles uniform)")};
  for (ParamDef& p : groove_common_params()) d.params.push_back(std::move(p));
  d.outputs = {{"closure", SocketType::kClosure, false, "the microgroove lobe"}};
  d.prepare = prepare_microgroove;
  d.eval = emit_microgroove;
  d.closure_traits = microgroove_traits;
  d.context_usage = kUsesGeometry;
  return d;
}

}  // namespace ochre
