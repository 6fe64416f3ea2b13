#include "materials/nodes/closures/groove_closure.h"

#include <array>
#include <cmath>
#include <numbers>

#include "materials/core/frame.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "spectra/named_spectra.h"

namespace ochre {

namespace {

constexpr std::array kChainModels{
    Choice{"rigorous", ChainModel::kRigorous}, Choice{"unpolarized", ChainModel::kUnpolarized},
    Choice{"sp", ChainModel::kSeparateSP}, Choice{"paper_literal", ChainModel::kPaperLiteral}};
constexpr std::array kDirectionSpaces{Choice{"uv", DirectionSpace::kUV},
                                      Choice{"object", DirectionSpace::kObject},
                                      Choice{"world", DirectionSpace::kWorld}};

// The reference direction in world space.
Vec3 reference_direction(const NodeArgs& a, DirectionSpace space, int direction_input) {
  if (space == DirectionSpace::kUV) return a.ctx.dpdu;
  const Vec3 v = a.in_vector(direction_input);
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

}  // namespace

GrooveFacetSettings parse_groove_settings(const PrepareArgs& args) {
  GrooveFacetSettings s;
  s.model = choice_value(args, "model", kChainModels);
  s.space = choice_value(args, "direction_space", kDirectionSpaces);
  if (const std::optional<std::string> metal = choice_name(args, "metal"); metal == "mirror") {
    s.mirror = true;
  } else if (metal) {
    s.eta = named_spectrum("metal-" + *metal + "-eta");
    s.k = named_spectrum("metal-" + *metal + "-k");
  }
  if (args.params.contains("max_reflections"))
    s.reflection_limit = args.params.at("max_reflections").get<int>();
  return s;
}

FacetSpectrum groove_facet(const NodeArgs& a, const GrooveFacetSettings& s, const GrooveInputs& in) {
  FacetSpectrum facet;
  facet.mirror = s.mirror;
  facet.n = s.eta ? s.eta->sample(a.lambda()) : a.in_spectrum(in.eta);
  facet.k = s.k ? s.k->sample(a.lambda()) : a.in_spectrum(in.k);
  return facet;
}

Vec3 groove_local_axis(const NodeArgs& a, const GrooveFacetSettings& s, const GrooveInputs& in) {
  const Vec3& n = a.ctx.n;
  const float angle = a.in_float(in.angle) * (std::numbers::pi_v<float> / 180.0f);
  const Vec3 reference = tangent_of(n, reference_direction(a, s.space, in.direction));
  const Vec3 groove = reference * std::cos(angle) + cross(n, reference) * std::sin(angle);
  if (!a.has_tangent()) {
    a.set_tangent(groove);
    return {1.0f, 0.0f, 0.0f};
  }
  const Vec3 x = tangent_of(n, a.tangent());
  return {dot(groove, x), dot(groove, cross(n, x)), 0.0f};
}

ClosureTraits groove_traits(const GrooveFacetSettings& s) {
  return {kLobeReflection | kLobeDelta | (groove_model_polarizes(s.model) ? kLobePolarizing : 0u), false};
}

std::vector<SocketDef> groove_facet_and_direction_inputs() {
  return {named_spectrum_input("eta", "metal-Cu-eta", "real part n of the facets' index (default: copper)"),
          named_spectrum_input("k", "metal-Cu-k",
                               "extinction coefficient k >= 0 (0: a dielectric, e.g. black glass)"),
          float_input("angle", SocketType::kFloat, 0.0f, kAnyValue,
                      "groove direction: degrees from the reference direction, counter-clockwise about "
                      "the normal (may be textured)"),
          vector_input("direction", {1.0f, 0.0f, 0.0f},
                       "reference groove direction in object or world space (see direction_space); ignored "
                       "for uv")};
}

std::vector<ParamDef> groove_common_params() {
  return {
      optional_choice_param("metal", {"Au", "Ag", "Cu", "Al", "Si", "mirror"},
                            "built-in optical constants of the facets (mirror: reflectance 1, no "
                            "retardance); when given, eta and k are ignored"),
      research_param(choice_param("model", "rigorous", choice_names(kChainModels),
                                  "polarization treatment: rigorous Mueller chain; unpolarized (product of "
                                  "unpolarized reflectances); sp (s and p reflected separately, averaged); "
                                  "paper_literal (the printed Eq 33, for comparison only)")),
      research_param(
          integer_param("max_reflections", 0, 0, 100000,
                        "rays needing more reflections are absorbed (the paper's Table 3); 0 = no limit")),
      choice_param("direction_space", "uv", choice_names(kDirectionSpaces),
                   "reference direction: the mesh's dp/du (uv), or the `direction` input in object "
                   "or world space")};
}

}  // namespace ochre
