#pragma once
// Unidirectional spectral path tracer: next-event estimation, multiple importance sampling
// (power heuristic) between light and BSDF sampling, Russian roulette, delta lobes and delta
// lights handled. Radiance is traced for the 8 hero wavelengths of the path, carrying the Mueller
// product of the polarization mode (path_throughput.h): off, intensity or stokes. With
// integrator.branches = k, each camera sample continues from its first non-delta vertex along k paths,
// averaged (docs/architecture.md#branched-paths).

#include <algorithm>
#include <array>
#include <cstdint>

#include "materials/lobes/lobe_arena.h"
#include "renderer/integrator/path_guide.h"
#include "renderer/integrator/path_throughput.h"
#include "renderer/sampling/sampler.h"
#include "renderer/sampling/sobol_sampler.h"
#include "renderer/scene/polarization_mode.h"
#include "renderer/scene/scene.h"

namespace ochre {

// What the camera ray saw first, for the AOV layers of the EXR (albedo, normal, depth).
struct FirstHit {
  bool hit = false;
  SampledSpectrum albedo;  // sum of lobe weights x directional albedo estimates
  Vec3 normal;             // world-space shading normal, facing the camera
  float depth = 0.0f;      // distance along the camera ray
};

struct PathStats {
  uint64_t rays = 0;         // camera + continuation rays (rtcIntersect1)
  uint64_t shadow_rays = 0;  // rtcOccluded1
};

template <class Throughput>
struct PathState;

// One camera sample of the pilot that chooses the branch count (branch_choice.h): the radiance (S0) of the
// shared part of a branched path (camera to its first non-delta vertex, with that vertex's light sample) and
// of each of two continuations from there, and the rays each traced.
struct BranchPilotSample {
  bool branched = false;  // false: the path ended before a branch point (everything is in `shared`)
  SampledSpectrum shared{0.0f};
  std::array<SampledSpectrum, 2> branch{SampledSpectrum(0.0f), SampledSpectrum(0.0f)};
  uint64_t shared_rays = 0, shared_shadow_rays = 0;  // of the shared part
  uint64_t branch_rays = 0, branch_shadow_rays = 0;  // of both continuations together
};

// Where light arriving along a path goes: the path's radiance L and, with light groups, the S0 of each group
// (docs/lights.md, "Light groups"), which sum to L's S0.
struct LightSink {
  SensorStokes& L;
  SampledSpectrum* groups = nullptr;  // one per group of the scene, or null: no groups
  float group_weight = 1.0f;          // a branch's share (1 / branches) of a branched path
};

class PathIntegrator {
 public:
  PathIntegrator(const Scene& scene, const RenderSettings& settings, PolarizationMode mode)
      : scene_(scene),
        mode_(mode),
        local_lights_(scene.local_light_selection(settings.light_selection)),
        all_lights_(settings.light_selection == LightSelection::kAll && scene.lights.size() >= 2),
        last_bounce_finds_light_(scene.rays_find_emission()),
        guide_(settings.guide.get()),
        branches_(static_cast<uint32_t>(std::max(1, settings.branches))),
        max_depth_(static_cast<uint32_t>(std::max(0, settings.max_depth))),
        rr_depth_(static_cast<uint32_t>(settings.rr_depth == RenderSettings::kAutoRoulette
                                            ? RenderSettings::kDefaultRouletteDepth
                                            : std::max(0, settings.rr_depth))) {}

  // What the camera ray's sensor pixel receives for the path's wavelengths: S0 (index 0), and S1..S3 in
  // mode stokes (in the camera's frame: x along the image x axis, y up). Random numbers come from
  // `sampler`. `cone` is the camera ray's footprint, used to filter textures.
  // Instantiated for IndependentSampler and SobolSampler.
  // `groups`: with light groups, one spectrum per group of the scene, zero on entry, receives the S0 each
  // group's lights give (null: none).
  template <class Sampler>
  SensorStokes radiance(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                        const Sampler& sampler, LobeArena& arena, PathStats& stats,
                        FirstHit* first_hit = nullptr, SampledSpectrum* groups = nullptr) const;

  // A camera sample of the branch-count pilot (branch_choice.h): two continuations from the first non-delta
  // vertex, whatever integrator.branches is, their radiance kept apart from the shared part's.
  template <class Sampler>
  BranchPilotSample pilot_sample(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                                 const Sampler& sampler, LobeArena& arena) const;

  // A path of the guide's training (guide_training.h), one branch: what arrived along each direction it
  // scattered into, appended to `out` (path_guide.h).
  template <class Sampler>
  void guide_training_path(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                           const Sampler& sampler, LobeArena& arena, std::vector<GuideRecord>& out) const;

 private:
  // Arrival of s.ray: emission, shading and next-event estimation at the vertex it hits (stored in v).
  // False when the path ends there. Lobes go to `arena` above `arena_floor`; `own_lobes`: never in the
  // per-thread memo (the vertex must outlive later ones).
  template <class Sampler, class Throughput>
  bool arrive(PathState<Throughput>& s, struct PathVertex& v, uint32_t depth, const RayCone& cone,
              const SampledWavelengths& lambda, const Sampler& sampler, LobeArena& arena, size_t arena_floor,
              bool own_lobes, PathStats& stats, FirstHit* first_hit) const;
  // BSDF sampling at v, Russian roulette and the next ray. False when the path ends.
  template <class Sampler, class Throughput>
  bool scatter(PathState<Throughput>& s, const struct PathVertex& v, uint32_t depth,
               const SampledWavelengths& lambda, const Sampler& sampler) const;
  // Scattering at a vertex with a guide cell: the guide or the BSDF, weighted by their mixture's density
  // (path_guide.h). Sets wi (world) and its pdf; false when the path ends.
  template <class Throughput>
  bool guided_scatter(PathState<Throughput>& s, const struct PathVertex& v, const Vec3& wo, float u_lobe,
                      const Vec2& u, const SampledWavelengths& lambda, Vec3& wi, float& pdf) const;
  // The density scatter() samples wi with (local wi_local, world wi): the BSDF's, mixed with the guide's
  // where the vertex has a cell. The BSDF side of every MIS weight.
  float scatter_pdf(const struct PathVertex& v, const Vec3& wi_local, const Vec3& wi,
                    const SampledWavelengths& lambda) const;
  template <class Sampler, class Throughput>
  void record_training_path(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                            const Sampler& sampler, LobeArena& arena, std::vector<GuideRecord>& out) const;
  // traced.operator()<T>() for the throughput policy T of the polarization mode (path_throughput.h).
  template <class Traced>
  auto with_throughput(const Traced& traced) const;
  // A path's state as the camera ray leaves (the camera's analyzer and Stokes frame).
  template <class Throughput>
  PathState<Throughput> camera_state(const Ray& camera_ray, SampledSpectrum* groups) const;
  // The shared part of a branched path: from the camera to its first vertex with a non-delta lobe (v, at
  // `depth`), whose lobes stay in `arena`. False when the path ends before.
  template <class Sampler, class Throughput>
  bool trace_shared(PathState<Throughput>& s, struct PathVertex& v, uint32_t& depth, const RayCone& cone,
                    const SampledWavelengths& lambda, const Sampler& sampler, LobeArena& arena,
                    PathStats& stats, FirstHit* first_hit) const;
  // Continuation j of k from the shared vertex v: its own radiance (not divided by k). Its lobes use the
  // arena above `floor`.
  template <class Sampler, class Throughput>
  SensorStokes continue_branch(const PathState<Throughput>& shared, const struct PathVertex& v,
                               uint32_t depth, uint32_t j, uint32_t k, const RayCone& cone,
                               const SampledWavelengths& lambda, const Sampler& sampler, LobeArena& arena,
                               size_t floor, PathStats& stats) const;
  template <class Sampler, class Throughput>
  BranchPilotSample pilot_trace(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                                const Sampler& sampler, LobeArena& arena) const;
  template <class Sampler, class Throughput>
  SensorStokes trace(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                     const Sampler& sampler, LobeArena& arena, PathStats& stats, FirstHit* first_hit,
                     SampledSpectrum* groups) const;
  // The light group of light `light` (-1: an emitter that is no light), -1 without groups.
  int group_of(int light) const {
    if (scene_.light_groups.empty()) return -1;
    return light >= 0 ? scene_.light_group_of[static_cast<size_t>(light)] : scene_.other_light_group;
  }
  // Next-event estimation at a surface point: one light sample (or one of every light), MIS-weighted, added
  // to L. `pmfs`: the lights' probabilities at this point (Scene::light_pmfs), or null to choose by power.
  template <class Sampler, class Throughput>
  void direct_light(const struct PathVertex& v, const Vec3& wo, const Throughput& throughput,
                    const SampledWavelengths& lambda, const Sampler& sampler, uint32_t depth,
                    const Scene::LightPmfs* pmfs, PathStats& stats, const LightSink& sink) const;
  // A sample of light `index` at position numbers `u`, chosen with probability `pmf` (1: every light is
  // sampled), through a shadow ray.
  template <class Throughput>
  void sample_light(const struct PathVertex& v, const Vec3& wo, const Throughput& throughput,
                    const SampledWavelengths& lambda, size_t index, float pmf, const Vec2& u,
                    PathStats& stats, const LightSink& sink) const;
  // The probability next-event estimation gives light `light` at the vertex whose light pmfs `pmfs` holds.
  float light_choice_pmf(int light, const Scene::LightPmfs& pmfs) const {
    if (all_lights_) return 1.0f;
    return local_lights_ ? pmfs[static_cast<size_t>(light)] : scene_.light_pmf(light);
  }
  // Next-event estimation through a planar mirror: one sample of a light's mirror image (planar_mirrors.h),
  // the path x -> mirror -> light MIS-weighted against BSDF sampling of the same path.
  template <class Sampler, class Throughput>
  void mirrored_light(const struct PathVertex& v, const Vec3& wo, const Throughput& throughput,
                      const SampledWavelengths& lambda, const Sampler& sampler, uint32_t depth,
                      LobeArena& arena, PathStats& stats, const LightSink& sink) const;
  // Emission reached by a BSDF-sampled path x -> mirror -> light: the MIS weight against mirrored_light().
  float mirrored_emission_weight(int mirror, int light, const Vec3& x, float bsdf_pdf, const Vec3& p,
                                 const Vec3& ng) const;

  const Scene& scene_;
  PolarizationMode mode_;
  bool local_lights_;  // lights chosen per shading point (Scene::light_pmfs)
  bool all_lights_;    // every light sampled at each vertex (integrator.light_selection "all")
  // A ray from a path's last vertex can find light (Scene::rays_find_emission): else that bounce is not
  // taken.
  bool last_bounce_finds_light_;
  const PathGuide* guide_;  // learned incident light (integrator.guiding), or null
  uint32_t branches_;       // continuations of each camera sample from its first vertex (integrator.branches)
  uint32_t max_depth_;      // scattering events a path may have (integrator.max_depth)
  uint32_t rr_depth_;       // bounces before Russian roulette (integrator.rr_depth)
};

}  // namespace ochre
