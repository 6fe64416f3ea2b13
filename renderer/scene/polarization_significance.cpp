#include "renderer/scene/polarization_significance.h"

#include <algorithm>
#include <cmath>

#include "materials/core/pcg32.h"
#include "materials/core/sampling.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "renderer/geometry/surface_shading.h"

namespace ochre {

namespace {

constexpr int kPointsPerMaterial = 64;
constexpr int kDirectionPairsPerPoint = 16;
constexpr uint64_t kSeed = 0x9e3779b97f4a7c15ull;  // fixed: the estimate is the same on every run

// Sums over the evaluations of one material: M00, |M[0][1..3]| and |M[1..3][0]|.
struct MuellerSums {
  double m00 = 0, row = 0, column = 0;
  void add(const Mueller& m) {
    m00 += std::abs(m(0, 0));
    row += std::hypot(m(0, 1), m(0, 2), m(0, 3));
    column += std::hypot(m(1, 0), m(2, 0), m(3, 0));
  }
};

// One shading point of a mesh with the material, its closure evaluated for cosine-distributed direction
// pairs in the local shading frame.
void add_point(const Scene& scene, const Mesh& mesh, const CompiledMaterial& material, Pcg32& rng,
               LobeArena& arena, MuellerSums& sums) {
  const auto triangle = static_cast<uint32_t>(rng.next_uint() % mesh.triangle_count());
  float b1 = rng.next_float(), b2 = rng.next_float();
  if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
  const SurfacePoint sp = surface_point(mesh, triangle, b1, b2);
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(rng.next_float());
  const ShadingContext ctx =
      shading_context(sp, scene.origin.to_float(), lambda, scene.textures.get(), &mesh);
  arena.reset();
  Closure closure;
  material.evaluate(ctx, arena, closure);
  if (!closure.has_lobes()) return;
  for (int pair = 0; pair < kDirectionPairsPerPoint; ++pair) {
    const Vec3 wo = sample_cosine_hemisphere({rng.next_float(), rng.next_float()});
    const Vec3 wi = sample_cosine_hemisphere({rng.next_float(), rng.next_float()});
    const MuellerResponse r = closure.eval_mueller(wo, wi, lambda);
    for (const Mueller& m : r.m) sums.add(m);
  }
}

}  // namespace

PolarizationSignificance polarization_significance(const Scene& scene) {
  PolarizationSignificance out;
  LobeArena arena;
  Pcg32 rng(kSeed);
  for (size_t index = 0; index < scene.materials.size(); ++index) {
    const CompiledMaterial& material = *scene.materials[index];
    if (!material.facts().polarizes) continue;
    if (material.facts().has_delta_lobes) {
      out.delta_lobes = true;
      continue;
    }
    std::vector<const Mesh*> users;
    for (const Mesh& mesh : scene.meshes)
      if (mesh.material == static_cast<int>(index) && mesh.triangle_count() > 0) users.push_back(&mesh);
    if (users.empty()) continue;
    MuellerSums sums;
    for (int point = 0; point < kPointsPerMaterial; ++point)
      add_point(scene, *users[rng.next_uint() % users.size()], material, rng, arena, sums);
    if (!(sums.m00 > 0.0)) continue;
    out.diattenuation = std::max(out.diattenuation, sums.row / sums.m00);
    out.polarizance = std::max(out.polarizance, sums.column / sums.m00);
  }
  return out;
}

}  // namespace ochre
