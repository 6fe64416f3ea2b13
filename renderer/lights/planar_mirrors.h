#pragma once
// Planar mirrors and the images of the lights seen in them (docs/architecture.md, 'Lights seen in planar
// mirrors').
//
// Light that reaches a diffuse point x through a perfect mirror comes, for a path tracer that only samples
// the light directly, from a direction BSDF sampling must hit by chance: a diffuse -> mirror -> light path
// is a caustic. When the mirror is a plane the path can be sampled exactly: x' = x reflected in the plane
// sees the light where x sees its mirror image, so a point y sampled on the light as seen from x' gives
// the path x -> m -> y, m where the segment x' y crosses the plane, and the solid-angle pdf the light
// gives from x' is the pdf of the direction x -> m (reflection keeps lengths and angles). It is the
// one-vertex case of manifold next-event estimation (Hanika, Droske and Fascione 2015), solved in closed
// form; the integrator weighs it against BSDF sampling of the same path by MIS.
//
// A mesh is a planar mirror when its triangles lie in one plane, its shading normals (if any) are that
// plane's normal, and its material, the same everywhere on the surface (MaterialFacts::
// uniform_over_surface), evaluates to one perfect-mirror lobe (kLobeMirror: a smooth conductor or an
// opaque smooth dielectric). Such a mesh reflects on both sides, as every reflection-only closure does.

#include <optional>
#include <vector>

#include "materials/graph/compiled_material.h"
#include "renderer/geometry/mesh.h"
#include "renderer/lights/light.h"
#include "renderer/sampling/distribution_1d.h"

namespace ochre {

struct PlanarMirror {
  int mesh = -1;
  Vec3 normal;          // unit normal of the plane dot(normal, p) = offset
  float offset = 0.0f;  // (either orientation: the mirror reflects on both sides)
  float area = 0.0f;

  float signed_distance(const Vec3& p) const { return dot(normal, p) - offset; }
  Vec3 reflect_point(const Vec3& p) const { return p - normal * (2.0f * signed_distance(p)); }
  Vec3 reflect_direction(const Vec3& d) const { return d - normal * (2.0f * dot(normal, d)); }
};

// The mesh's plane if it is a planar mirror (see above), else nothing.
std::optional<PlanarMirror> planar_mirror(const Mesh& mesh, int mesh_index, const CompiledMaterial& material);

// Every pair (planar mirror, light at a finite distance), chosen in proportion to the light's selection
// probability (its power), the same for every mirror.
class MirrorLights {
 public:
  // At most this many mirrors, the largest first: each one dilutes the samples of the others.
  static constexpr size_t kMaxMirrors = 16;

  // Finds the planar mirrors among `meshes`; `infinite_light` (the environment, -1 if none) has no image.
  void build(const std::vector<Mesh>& meshes,
             const std::vector<std::shared_ptr<const CompiledMaterial>>& materials, size_t light_count,
             int infinite_light);
  // Recomputes the pair probabilities from the lights' selection pmf (after their powers change).
  void update_selection(const Distribution1D& light_selection);

  bool empty() const { return selection_.empty(); }
  const std::vector<PlanarMirror>& mirrors() const { return mirrors_; }
  // Index into mirrors() of a mesh, or -1 when the mesh is not a planar mirror.
  int mirror_of_mesh(size_t mesh) const { return mesh < mirror_of_mesh_.size() ? mirror_of_mesh_[mesh] : -1; }

  struct Choice {
    const PlanarMirror* mirror = nullptr;
    int light = -1;
    float pmf = 0.0f;
  };
  Choice sample(float u) const;
  // Probability that sample() picks (mirror, light); 0 for a light without images.
  float pmf(int mirror, int light) const;

 private:
  std::vector<PlanarMirror> mirrors_;
  std::vector<int> mirror_of_mesh_;
  std::vector<int> lights_;         // the lights with images, by scene index
  std::vector<int> slot_of_light_;  // scene light index -> position in lights_, or -1
  Distribution1D selection_;        // over mirror * lights_.size() + slot
};

}  // namespace ochre
