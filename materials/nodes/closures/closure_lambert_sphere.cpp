// lambert_sphere(kd | particle_albedo, variant, mapping): the Lambertian-sphere BRDF of d'Eon
// (materials/lobes/lambert_sphere/lambert_sphere_lobe.h), a half space of sparse white-Lambertian spheres.
// Its colour is set either by the bond (spherical) albedo kd, mapped to the particle albedo c, or by c
// directly.

#include <array>
#include <memory>

#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "materials/nodes/definition_builders.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_definition.h"

namespace ochre {

namespace {

// kd -> c: the inverse of the model's own bond albedo, or d'Eon's Eq 46.
enum class KdMapping { kExact, kEq46 };

constexpr std::array kSphereVariants{Choice{"full", LambertSphereVariant::kFull},
                                     Choice{"fast", LambertSphereVariant::kFast},
                                     Choice{"exact", LambertSphereVariant::kExact}};
constexpr std::array kKdMappings{Choice{"exact", KdMapping::kExact}, Choice{"eq46", KdMapping::kEq46}};

struct LambertSphereSettings {
  LambertSphereVariant variant = LambertSphereVariant::kFull;
  KdMapping mapping = KdMapping::kExact;
};

Prepared prepare_lambert_sphere(const PrepareArgs& args) {
  auto s = std::make_shared<LambertSphereSettings>();
  s->variant = choice_value(args, "variant", kSphereVariants);
  s->mapping = choice_value(args, "mapping", kKdMappings);
  Prepared p;
  p.payload = s;
  return p;
}

void emit_lambert_sphere(const NodeArgs& a) {
  SampledSpectrum w = a.weight();
  if (w.is_black()) return;
  const LambertSphereSettings& s = a.data<LambertSphereSettings>();
  const SampledSpectrum kd = a.in_spectrum(0), particle_albedo = a.in_spectrum(1);
  bool uses_kd = false;  // particle_albedo < 0 (or NaN) in some lane
  for (int k = 0; k < kSpectrumSamples; ++k) uses_kd |= !(particle_albedo[k] >= 0.0f);
  SampledSpectrum c;
  if (uses_kd && s.mapping == KdMapping::kEq46) {
    for (int k = 0; k < kSpectrumSamples; ++k) c[k] = lambert_sphere_c_from_kd_eq46(kd[k]);
  } else if (uses_kd) {
    const BondAlbedoInverse& inverse = s.variant == LambertSphereVariant::kExact
                                           ? lambert_sphere_exact_kd_inverse()
                                           : lambert_sphere_kd_inverse();
    inverse.c(kd.lanes(), c.lanes());
    // Above the largest bond albedo the model reaches (the fitted model loses up to 1.4 % at c = 1), the
    // weight makes up the difference so that the rendered bond albedo is kd.
    for (int k = 0; k < kSpectrumSamples; ++k)
      if (!(particle_albedo[k] >= 0.0f)) w[k] *= inverse.weight_scale(kd[k]);
  }
  for (int k = 0; k < kSpectrumSamples; ++k)
    if (particle_albedo[k] >= 0.0f) c[k] = particle_albedo[k];  // given: replaces the value from kd
  a.add_lobe(a.arena.make<LambertSphereLobe>(s.variant, c), w);
}

ClosureTraits lambert_sphere_traits(std::span<const InputView>, const void*) {
  return {kLobeReflection | kLobeDiffuse, false};
}

}  // namespace

NodeDefinition lambert_sphere_node() {
  NodeDefinition d;
  d.name = "lambert_sphere";
  d.doc =
      "Lambertian-sphere BRDF (d'Eon): a half space of sparse white-Lambertian spheres; strong "
      "backscattering, saturated colours. A depolarizer.";
  d.inputs = {
      reflectance_input("kd", 0.8f, clamped_range(0.0f, 1.0f),
                        "bond (spherical) albedo, the diffuse colour; mapped to the particle albedo by "
                        "`mapping`"),
      reflectance_input("particle_albedo", -1.0f, kAnyValue,
                        "albedo c of the spheres; when >= 0 it is used instead of kd (default -1: use "
                        "kd)")};
  d.params = {choice_param("variant", "full", choice_names(kSphereVariants),
                           "full: exact single + corrected fitted multiple scattering; fast: Eq 48 (not "
                           "energy conserving); exact: tabulated converged half-space solution"),
              research_param(choice_param(
                  "mapping", "exact", choice_names(kKdMappings),
                  "kd -> c: exact inverts the model's own bond albedo (< 0.5 % error); eq46 is the "
                  "paper's fit (renders up to 3.8 % too bright)"))};
  d.outputs = {{"closure", SocketType::kClosure, false, "the Lambert-sphere lobe"}};
  d.prepare = prepare_lambert_sphere;
  d.eval = emit_lambert_sphere;
  d.closure_traits = lambert_sphere_traits;
  return d;
}

}  // namespace ochre
