// vgroove(alpha, eta, k, angle, direction; metal, model, max_reflections, direction_space): a surface
// of parallel specular V-grooves as an analytic delta BSDF (materials/lobes/vgroove/vgroove_lobe.h,
// Saint-Pierre et al. 2019). The groove axis lies in the tangent plane: the reference direction
// (the mesh's dp/du, or `direction` in object or world space) projected onto the tangent plane and
// turned by `angle` degrees about the normal.

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "materials/core/frame.h"
#include "materials/lobes/vgroove/vgroove_lobe.h"
#include "materials/nodes/node_definition.h"
#include "spectra/named_spectra.h"

namespace ochre {

namespace {

enum class DirectionSpace { kUV, kObject, kWorld };

struct VGrooveSettings {
  SpectrumPtr eta, k;  // named optical constants, or null (the eta and k inputs)
  bool mirror = false;
  ChainModel model = ChainModel::kRigorous;
  int reflection_limit = 0;
  DirectionSpace space = DirectionSpace::kUV;
};

constexpr float kMinAlphaDegrees = 0.1f;  // a ray can need 1800 reflections there

std::string string_param(const PrepareArgs& args, const char* name, const char* fallback) {
  return args.params.contains(name) ? args.params.at(name).get<std::string>() : fallback;
}

ChainModel parse_model(const std::string& model) {
  if (model == "unpolarized") return ChainModel::kUnpolarized;
  if (model == "sp") return ChainModel::kSeparateSP;
  if (model == "paper_literal") return ChainModel::kPaperLiteral;
  return ChainModel::kRigorous;
}

Prepared prepare_vgroove(const PrepareArgs& args) {
  auto s = std::make_shared<VGrooveSettings>();
  const std::string metal = string_param(args, "metal", "");
  if (metal == "mirror") {
    s->mirror = true;
  } else if (!metal.empty()) {
    s->eta = named_spectrum("metal-" + metal + "-eta");
    s->k = named_spectrum("metal-" + metal + "-k");
  }
  s->model = parse_model(string_param(args, "model", "rigorous"));
  if (args.params.contains("max_reflections")) s->reflection_limit = args.params.at("max_reflections").get<int>();
  const std::string space = string_param(args, "direction_space", "uv");
  s->space = space == "object" ? DirectionSpace::kObject
                               : (space == "world" ? DirectionSpace::kWorld : DirectionSpace::kUV);
  Prepared p;
  p.payload = s;
  return p;
}

// The reference direction in world space.
Vec3 reference_direction(const NodeArgs& a, DirectionSpace space) {
  if (space == DirectionSpace::kUV) return a.ctx.dpdu;
  const Vec3 v = a.in_vector(4);
  if (space == DirectionSpace::kWorld || !a.ctx.object_axes) return v;
  const Vec3* axes = a.ctx.object_axes;
  return axes[0] * v.x + axes[1] * v.y + axes[2] * v.z;
}

// Unit vector of the tangent plane of n nearest to t (any tangent when t is along n).
Vec3 tangent_of(const Vec3& n, const Vec3& t) {
  const Vec3 projected = t - n * dot(n, t);
  const float len = length(projected);
  return len > 1e-6f ? projected / len : Frame::from_normal(n).s;
}

void emit_vgroove(const NodeArgs& a) {
  const SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  const VGrooveSettings& s = a.data<VGrooveSettings>();
  const Vec3& n = a.ctx.n;
  const float angle = a.in_float(3) * (std::numbers::pi_v<float> / 180.0f);
  const Vec3 reference = tangent_of(n, reference_direction(a, s.space));
  const Vec3 groove = reference * std::cos(angle) + cross(n, reference) * std::sin(angle);

  // Local axis: x when this closure sets the tangent; relative to the tangent already set otherwise.
  Vec3 axis(1.0f, 0.0f, 0.0f);
  if (a.closure.has_tangent()) {
    const Vec3 x = tangent_of(n, a.closure.tangent());
    axis = {dot(groove, x), dot(groove, cross(n, x)), 0.0f};
  } else {
    a.closure.set_tangent(groove);
  }

  FacetSpectrum facet;
  facet.mirror = s.mirror;
  facet.n = s.eta ? s.eta->sample(a.lambda()) : a.in_spectrum(1);
  facet.k = s.k ? s.k->sample(a.lambda()) : a.in_spectrum(2);
  const float alpha_degrees = std::clamp(a.in_float(0), kMinAlphaDegrees, 180.0f);
  a.closure.add_lobe(a.arena.make<VGrooveLobe>(alpha_degrees * (std::numbers::pi / 180.0), axis, facet,
                                               s.model, s.reflection_limit),
                     w);
}

ClosureTraits vgroove_traits(std::span<const InputView>, const void* payload) {
  const auto& s = *static_cast<const VGrooveSettings*>(payload);
  const bool polarizing = s.model == ChainModel::kRigorous || s.model == ChainModel::kSeparateSP;
  return {kLobeReflection | kLobeDelta | (polarizing ? kLobePolarizing : 0u), false};
}

SocketDef float_input(const char* name, float fallback, std::optional<float> min, std::optional<float> max,
                      const char* doc) {
  SocketDef s;
  s.name = name;
  s.type = SocketType::kFloat;
  s.default_value = NodeValue::of_float(fallback);
  s.min = min;
  s.max = max;
  s.clamped = min.has_value();
  s.doc = doc;
  return s;
}

SocketDef spectrum_input(const char* name, const char* named_default, const char* doc) {
  SocketDef s;
  s.name = name;
  s.type = SocketType::kSpectrum;
  s.default_value = NodeValue::of_spectrum(named_spectrum(named_default));
  s.role = SpectralRole::kNone;
  s.min = 0.0f;
  s.doc = doc;
  return s;
}

ParamDef choice_param(const char* name, const char* fallback, std::vector<std::string> choices, const char* doc) {
  ParamDef p;
  p.name = name;
  p.kind = ParamKind::kString;
  p.default_value = fallback;
  p.choices = std::move(choices);
  p.doc = doc;
  return p;
}

}  // namespace

NodeDefinition vgroove_node() {
  NodeDefinition d;
  d.name = "vgroove";
  d.doc =
      "Parallel V-grooves with specular facets (Saint-Pierre et al. 2019): a delta BSDF whose rays "
      "reflect 1, 2, ... times inside a groove, traced exactly; polarizing in the rigorous and sp models.";
  SocketDef direction;
  direction.name = "direction";
  direction.type = SocketType::kVector;
  direction.default_value = NodeValue::of_vector({1.0f, 0.0f, 0.0f});
  direction.doc = "reference groove direction in object or world space (see direction_space); ignored for uv";
  d.inputs = {float_input("alpha", 90.0f, kMinAlphaDegrees, 180.0f,
                          "dihedral (opening) angle of the grooves in degrees; 180 = flat; a linked value is "
                          "clamped to [0.1, 180]"),
              spectrum_input("eta", "metal-Cu-eta", "real part n of the facets' index (default: copper)"),
              spectrum_input("k", "metal-Cu-k", "extinction coefficient k >= 0 (0: a dielectric, e.g. black glass)"),
              float_input("angle", 0.0f, std::nullopt, std::nullopt,
                          "groove direction: degrees from the reference direction, counter-clockwise about the "
                          "normal (may be textured)"),
              direction};
  ParamDef max_reflections;
  max_reflections.name = "max_reflections";
  max_reflections.kind = ParamKind::kInt;
  max_reflections.default_value = 0;
  max_reflections.min = 0;
  max_reflections.max = 100000;
  max_reflections.doc = "rays needing more reflections are absorbed (the paper's Table 3); 0 = no limit";
  ParamDef metal = choice_param("metal", "", {"Au", "Ag", "Cu", "Al", "Si", "mirror"},
                                "built-in optical constants of the facets (mirror: reflectance 1, no "
                                "retardance); when given, eta and k are ignored");
  metal.default_value = nullptr;  // absent: the eta and k inputs
  d.params = {metal,
              choice_param("model", "rigorous", {"rigorous", "unpolarized", "sp", "paper_literal"},
                           "polarization treatment: rigorous Mueller chain; unpolarized (product of "
                           "unpolarized reflectances); sp (s and p reflected separately, averaged); "
                           "paper_literal (the printed Eq 33, for comparison only)"),
              max_reflections,
              choice_param("direction_space", "uv", {"uv", "object", "world"},
                           "reference direction: the mesh's dp/du (uv), or the `direction` input in object or "
                           "world space")};
  d.outputs = {{"closure", SocketType::kClosure, false, "the V-groove lobe"}};
  d.prepare = prepare_vgroove;
  d.eval = emit_vgroove;
  d.closure_traits = vgroove_traits;
  d.context_usage = kUsesGeometry;
  return d;
}

}  // namespace ochre
