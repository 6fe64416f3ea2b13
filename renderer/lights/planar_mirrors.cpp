#include "renderer/lights/planar_mirrors.h"

#include <algorithm>
#include <cmath>

#include "materials/lobes/lobe_arena.h"
#include "renderer/geometry/surface_shading.h"

namespace ochre {

namespace {

// Vertices within 1e-5 of the mesh's size from the plane; shading normals within 0.26 degrees of its normal.
constexpr float kPlaneTolerance = 1e-5f;
constexpr float kNormalCosine = 1.0f - 1e-5f;

Vec3 triangle_cross(const Mesh& mesh, size_t t) {
  const Vec3& a = mesh.positions[mesh.indices[3 * t]];
  const Vec3& b = mesh.positions[mesh.indices[3 * t + 1]];
  const Vec3& c = mesh.positions[mesh.indices[3 * t + 2]];
  return cross(b - a, c - a);
}

// The plane of the mesh's largest triangle, if every vertex lies in it.
std::optional<PlanarMirror> mesh_plane(const Mesh& mesh) {
  if (mesh.triangle_count() == 0) return std::nullopt;
  size_t largest = 0;
  float largest_length = 0.0f;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const float l = length(triangle_cross(mesh, t));
    if (l > largest_length) largest_length = l, largest = t;
  }
  if (!(largest_length > 0.0f)) return std::nullopt;
  PlanarMirror plane;
  plane.normal = triangle_cross(mesh, largest) / largest_length;
  plane.offset = dot(plane.normal, mesh.positions[mesh.indices[3 * largest]]);
  const Mesh::Bounds box = mesh.bounds();
  const float tolerance = kPlaneTolerance * std::max(length(box.hi - box.lo), 1e-20f);
  for (const Vec3& p : mesh.positions)
    if (std::abs(plane.signed_distance(p)) > tolerance) return std::nullopt;
  // Interpolated shading normals must be the plane's (one orientation, or interpolation could tilt them).
  if (!mesh.normals.empty()) {
    const float side = dot(mesh.normals[0], plane.normal) < 0.0f ? -1.0f : 1.0f;
    for (const Vec3& n : mesh.normals)
      if (side * dot(n, plane.normal) < kNormalCosine * length(n)) return std::nullopt;
  }
  plane.area = mesh.surface_area();
  return plane;
}

// Whether the material evaluates to one perfect-mirror lobe (and nothing else) wherever it is evaluated.
bool is_uniform_mirror_material(const CompiledMaterial& material, const Mesh& mesh,
                                const PlanarMirror& plane) {
  const MaterialFacts& facts = material.facts();
  if (!facts.uniform_over_surface || facts.is_emissive || !facts.has_delta_lobes) return false;
  const SampledWavelengths lambda = SampledWavelengths::sample_visible(0.5f);
  ShadingContext ctx;
  ctx.p = mesh.positions[mesh.indices[0]];
  ctx.n = plane.normal;
  ctx.object_axes = mesh.object_axes.data();
  ctx.lambda = &lambda;
  ctx.nonfinite = &thread_non_finite_tally();
  LobeArena arena;
  Closure closure;
  material.evaluate(ctx, arena, closure);
  return closure.lobe_count() == 1 && (closure.lobe(0).lobe->flags() & kLobeMirror) != 0 &&
         closure.emission().is_black();
}

}  // namespace

std::optional<PlanarMirror> planar_mirror(const Mesh& mesh, int mesh_index,
                                          const CompiledMaterial& material) {
  if (!material.facts().has_delta_lobes) return std::nullopt;  // cheap test before the geometry
  std::optional<PlanarMirror> plane = mesh_plane(mesh);
  if (!plane || !is_uniform_mirror_material(material, mesh, *plane)) return std::nullopt;
  plane->mesh = mesh_index;
  return plane;
}

void MirrorLights::build(const std::vector<Mesh>& meshes,
                         const std::vector<std::shared_ptr<const CompiledMaterial>>& materials,
                         size_t light_count, int infinite_light) {
  mirrors_.clear();
  for (size_t m = 0; m < meshes.size(); ++m)
    if (auto mirror = planar_mirror(meshes[m], static_cast<int>(m), *materials[meshes[m].material]))
      mirrors_.push_back(*mirror);
  std::stable_sort(mirrors_.begin(), mirrors_.end(),
                   [](const PlanarMirror& a, const PlanarMirror& b) { return a.area > b.area; });
  if (mirrors_.size() > kMaxMirrors) mirrors_.resize(kMaxMirrors);
  mirror_of_mesh_.assign(meshes.size(), -1);
  for (size_t i = 0; i < mirrors_.size(); ++i) mirror_of_mesh_[mirrors_[i].mesh] = static_cast<int>(i);

  lights_.clear();
  slot_of_light_.assign(light_count, -1);
  for (size_t l = 0; l < light_count; ++l) {
    if (static_cast<int>(l) == infinite_light) continue;
    slot_of_light_[l] = static_cast<int>(lights_.size());
    lights_.push_back(static_cast<int>(l));
  }
}

void MirrorLights::update_selection(const Distribution1D& light_selection) {
  std::vector<double> weights;
  if (!lights_.empty()) {
    weights.reserve(mirrors_.size() * lights_.size());
    for (size_t m = 0; m < mirrors_.size(); ++m)
      for (int light : lights_) weights.push_back(light_selection.pmf(static_cast<size_t>(light)));
  }
  selection_ = Distribution1D(weights);
}

MirrorLights::Choice MirrorLights::sample(float u) const {
  const size_t pair = selection_.sample(u);
  const size_t mirror = pair / lights_.size();
  return {&mirrors_[mirror], lights_[pair % lights_.size()], selection_.pmf(pair)};
}

float MirrorLights::pmf(int mirror, int light) const {
  if (empty() || mirror < 0 || light < 0 || static_cast<size_t>(light) >= slot_of_light_.size()) return 0.0f;
  const int slot = slot_of_light_[light];
  if (slot < 0) return 0.0f;
  return selection_.pmf(static_cast<size_t>(mirror) * lights_.size() + static_cast<size_t>(slot));
}

}  // namespace ochre
