#include "renderer/integrator/path_integrator.h"

#include <cmath>
#include <optional>

#include "materials/core/frame.h"
#include "materials/core/sampling.h"
#include "materials/graph/uniform_closure_memo.h"
#include "materials/lobes/closure.h"
#include "renderer/geometry/surface_shading.h"

namespace ochre {

// One scattering vertex of a path: geometry, shading frame and the evaluated closure.
struct PathVertex {
  SurfacePoint sp;
  Vec3 ng;  // unit geometric normal: on the side of wo, except for refracting closures (the mesh's own)
  Frame frame;
  Vec3 wo_local;
  Closure closure;
  uint32_t mesh = 0;
  bool guided = false;       // scattering samples the guide too (path_guide.h)
  PathGuide::Product guide;  // the vertex's cell times the cosine to its normal, where guided
};

namespace {

// Shading frame around the interpolated normal. For reflection-only closures it is flipped to the
// viewer's side of the surface (both sides of a mesh reflect alike), falling back to the geometric normal
// where the shading normal hides the viewer. Refracting closures need to know which side is outside: their
// frame keeps the mesh's orientation (the geometric normal points outside), so wo may be below it.
Frame shading_frame(const SurfacePoint& sp, const Vec3& ng, const Vec3& wo, bool keep_orientation,
                    const Closure& closure) {
  Vec3 ns = sp.ns;
  if (dot(ns, ng) < 0.0f) ns = -ns;
  if (!keep_orientation && dot(ns, wo) <= 0.0f) ns = ng;
  // Anisotropic lobes are defined about local x = the closure's tangent (closure.h).
  return closure.has_tangent() ? Frame::from_normal_tangent(ns, closure.tangent()) : Frame::from_normal(ns);
}

void record_first_hit(const PathVertex& v, float distance, const SampledWavelengths& lambda, FirstHit& out) {
  out.hit = true;
  out.depth = distance;
  out.normal = v.frame.n;
  out.albedo = SampledSpectrum(0.0f);
  for (int i = 0; i < v.closure.lobe_count(); ++i) {
    const WeightedLobe& l = v.closure.lobe(i);
    out.albedo += l.weight * l.lobe->albedo_hint(v.wo_local, lambda);
  }
}

// The lobe response at a vertex in world space, for the throughput policy T. In mode off (and for
// closures with no polarizing non-delta lobe) only M00 is computed.
template <class T>
WorldResponse vertex_response(const PathVertex& v, const Vec3& wo, const Vec3& wi_local,
                              const SampledWavelengths& lambda, std::optional<MuellerResponse>& storage) {
  WorldResponse r;
  r.wo = wo;
  if (!T::kPolarized || !v.closure.has_polarizing_non_delta_lobes()) {
    r.f = v.closure.eval(v.wo_local, wi_local, lambda);
    return r;
  }
  const MuellerResponse& m = storage.emplace(v.closure.eval_mueller(v.wo_local, wi_local, lambda));
  r.m = &m.m;
  r.f = m00(m.m);
  r.out_x = v.frame.to_world(m.out_x);
  r.in_x = v.frame.to_world(m.in_x);
  return r;
}

// The response of a sampled direction (weight = M00 |cos| / pdf already in bs.weight).
template <class T>
WorldResponse sampled_response(const PathVertex& v, const Vec3& wo, LobeSample& bs,
                               const SampledWavelengths& lambda) {
  WorldResponse r;
  r.wo = wo;
  r.f = bs.weight;
  if (!T::kPolarized) return r;
  if (bs.delta) {
    if (!bs.has_mueller) return r;
  } else {
    if (!v.closure.has_polarizing_non_delta_lobes()) return r;
    bs.mueller = v.closure.eval_mueller(v.wo_local, bs.wi, lambda);
    bs.mueller.m = bs.mueller.m * (abs_cos_theta(bs.wi) / bs.pdf);
  }
  r.m = &bs.mueller.m;
  r.out_x = v.frame.to_world(bs.mueller.out_x);
  r.in_x = v.frame.to_world(bs.mueller.in_x);
  return r;
}

// Picks an index with probabilities pmf[0..n) for u in [0, 1) (the last one with a non-zero pmf when rounding
// leaves u beyond the sum).
size_t pick_light(const Scene::LightPmfs& pmf, size_t n, float u) {
  float cdf = 0.0f;
  size_t last = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!(pmf[i] > 0.0f)) continue;
    cdf += pmf[i];
    last = i;
    if (u < cdf) break;
  }
  return last;
}

// The camera's Stokes x axis for a ray: the image x axis, made perpendicular to the ray.
Vec3 camera_stokes_axis(const Camera& camera, const Vec3& dir) {
  const Vec3 right = camera.basis().right;
  const Vec3 x = right - dir * dot(right, dir);
  const float len = length(x);
  return len > 1e-6f ? x / len : Frame::from_normal(dir).s;
}

// Light arriving along a path: `receive` adds it to the Stokes vector it is given. Without groups, straight
// into L (the bits of a render without groups); with them, into a fresh vector added to L and, its S0, to
// the light's group.
template <class Receive>
void deliver(const LightSink& sink, int group, const Receive& receive) {
  if (!sink.groups) {
    receive(sink.L);
    return;
  }
  SensorStokes c{};
  receive(c);
  for (size_t i = 0; i < c.size(); ++i) sink.L[i] += c[i];
  if (group >= 0) sink.groups[group] += c[0] * sink.group_weight;
}

}  // namespace

template <class Sampler, class T>
void PathIntegrator::direct_light(const PathVertex& v, const Vec3& wo, const T& throughput,
                                  const SampledWavelengths& lambda, const Sampler& sampler, uint32_t depth,
                                  const Scene::LightPmfs* pmfs, PathStats& stats,
                                  const LightSink& sink) const {
  if (all_lights_) {  // no choice, no selection noise: a shadow ray per light
    for (size_t i = 0; i < scene_.lights.size(); ++i)
      sample_light(v, wo, throughput, lambda, i, 1.0f,
                   sampler.get_2d(SampleDims::light_position(depth, static_cast<uint32_t>(i))), stats, sink);
    return;
  }
  // A single light is picked whatever the number: its dimension is not drawn.
  size_t index = 0;
  if (pmfs || scene_.light_selection.size() > 1) {
    const float u = sampler.get_1d(SampleDims::bounce(depth, SampleDims::kLightChoice));
    index = pmfs ? pick_light(*pmfs, scene_.lights.size(), u) : scene_.light_selection.sample(u);
  }
  const float pmf = pmfs ? (*pmfs)[index] : scene_.light_selection.pmf(index);
  if (!(pmf > 0.0f)) return;
  sample_light(v, wo, throughput, lambda, index, pmf,
               sampler.get_2d(SampleDims::bounce(depth, SampleDims::kLightPosition)), stats, sink);
}

template <class T>
void PathIntegrator::sample_light(const PathVertex& v, const Vec3& wo, const T& throughput,
                                  const SampledWavelengths& lambda, size_t index, float pmf, const Vec2& u,
                                  PathStats& stats, const LightSink& sink) const {
  const Light& light = *scene_.lights[index];
  const auto ls = light.sample(v.sp.p, u, lambda);
  if (!ls || !(ls->pdf > 0.0f) || ls->radiance.is_black()) return;
  const Vec3 wi_local = v.frame.to_local(ls->wi);
  if (dot(ls->wi, v.ng) * wi_local.z <= 0.0f) return;  // shading and geometric sides disagree
  std::optional<MuellerResponse> storage;  // only in polarized modes (0.5 KB not zeroed otherwise)
  const WorldResponse response = vertex_response<T>(v, wo, wi_local, lambda, storage);
  if (response.f.is_black()) return;
  const IncomingLight incoming = filtered_emission(light.polarizer_axis, -ls->wi, ls->radiance);
  if (incoming.radiance.is_black()) return;

  const Ray shadow =
      spawn_ray(v.sp, v.ng, ls->wi, std::isinf(ls->distance) ? INFINITY : ls->distance * (1.0f - 1e-4f));
  ++stats.shadow_rays;
  if (scene_.accel->occluded(shadow)) return;

  const float light_pdf = pmf * ls->pdf;
  const float mis = ls->delta || ls->only_by_light_sampling
                        ? 1.0f
                        : power_heuristic(light_pdf, scatter_pdf(v, wi_local, ls->wi, lambda));
  deliver(sink, group_of(static_cast<int>(index)), [&](SensorStokes& L) {
    throughput.receive_through(response, abs_cos_theta(wi_local) * mis / light_pdf, incoming, -ls->wi, L);
  });
}

template <class Sampler, class T>
void PathIntegrator::mirrored_light(const PathVertex& v, const Vec3& wo, const T& throughput,
                                    const SampledWavelengths& lambda, const Sampler& sampler, uint32_t depth,
                                    LobeArena& arena, PathStats& stats, const LightSink& sink) const {
  const MirrorLights::Choice choice =
      scene_.mirror_lights.sample(sampler.get_1d(SampleDims::bounce(depth, SampleDims::kMirrorLightChoice)));
  if (!(choice.pmf > 0.0f)) return;
  const PlanarMirror& mirror = *choice.mirror;
  const Light& light = *scene_.lights[choice.light];
  const float side = mirror.signed_distance(v.sp.p);
  if (side == 0.0f) return;
  // A point y on the light as seen from x's mirror image x' (planar_mirrors.h): x -> m -> y has the
  // direction and pdf of x' -> y reflected in the plane.
  const Vec2 u = sampler.get_2d(SampleDims::bounce(depth, SampleDims::kLightPosition));
  const Vec2 u_shifted{u.x < 0.5f ? u.x + 0.5f : u.x - 0.5f, u.y < 0.5f ? u.y + 0.5f : u.y - 0.5f};
  const Vec3 x_image = mirror.reflect_point(v.sp.p);
  const auto ls = light.sample(x_image, u_shifted, lambda);
  if (!ls || !(ls->pdf > 0.0f) || ls->radiance.is_black() || std::isinf(ls->distance)) return;
  const Vec3 y = x_image + ls->wi * ls->distance;
  if (mirror.signed_distance(y) * side <= 0.0f) return;  // the light is behind the mirror
  const Vec3 wi = mirror.reflect_direction(ls->wi);
  const Vec3 wi_local = v.frame.to_local(wi);
  if (dot(wi, v.ng) * wi_local.z <= 0.0f) return;  // shading and geometric sides disagree
  std::optional<MuellerResponse> storage;          // only in polarized modes (0.5 KB not zeroed otherwise)
  WorldResponse at_x = vertex_response<T>(v, wo, wi_local, lambda, storage);
  if (at_x.f.is_black()) return;
  const IncomingLight incoming = filtered_emission(light.polarizer_axis, -ls->wi, ls->radiance);
  if (incoming.radiance.is_black()) return;

  // The first surface toward the image must be the mirror itself, and the light visible from there.
  const Ray to_mirror = spawn_ray(v.sp, v.ng, wi);
  ++stats.rays;
  const auto hit = scene_.accel->intersect(to_mirror);
  if (!hit || static_cast<int>(hit->mesh) != mirror.mesh) return;
  PathVertex m;
  m.sp = surface_point(scene_.meshes, *hit, to_mirror);
  const Vec3 wo_m = -wi;
  m.ng = dot(m.sp.ng, wo_m) >= 0.0f ? m.sp.ng : -m.sp.ng;
  const Ray shadow = spawn_ray(m.sp, m.ng, ls->wi, length(y - m.sp.p) * (1.0f - 1e-4f));
  ++stats.shadow_rays;
  if (scene_.accel->occluded(shadow)) return;  // before the mirror's material: occluded samples skip it

  const Mesh& mesh = scene_.meshes[hit->mesh];
  const ShadingContext ctx =
      shading_context(m.sp, scene_.origin.to_float(), lambda, scene_.textures.get(), &mesh);
  scene_.materials[mesh.material]->evaluate(ctx, arena, m.closure);  // after v's lobes: v stays valid
  m.frame = shading_frame(m.sp, m.ng, wo_m, false, m.closure);
  m.wo_local = m.frame.to_local(wo_m);
  auto exit = m.closure.sample(m.wo_local, 0.5f, Vec2{0.5f, 0.5f}, lambda);  // the mirror's only exit
  if (!exit || exit->weight.is_black()) return;

  const float light_pdf = choice.pmf * ls->pdf;
  const float mis = ls->delta || ls->only_by_light_sampling
                        ? 1.0f
                        : power_heuristic(light_pdf, scatter_pdf(v, wi_local, wi, lambda));
  const float k = abs_cos_theta(wi_local) * mis / light_pdf;
  if (at_x.m) storage->m = storage->m * k;
  T through_mirror = throughput;
  through_mirror.scatter(at_x, at_x.f * k);
  deliver(sink, group_of(static_cast<int>(choice.light)), [&](SensorStokes& L) {
    through_mirror.receive_through(sampled_response<T>(m, wo_m, *exit, lambda), 1.0f, incoming, -ls->wi, L);
  });
}

float PathIntegrator::mirrored_emission_weight(int mirror, int light, const Vec3& x, float bsdf_pdf,
                                               const Vec3& p, const Vec3& ng) const {
  const float pmf = scene_.mirror_lights.pmf(mirror, light);
  if (!(pmf > 0.0f)) return 1.0f;
  const auto& area = static_cast<const AreaLight&>(*scene_.lights[light]);
  const Vec3 x_image = scene_.mirror_lights.mirrors()[mirror].reflect_point(x);
  return power_heuristic(bsdf_pdf, pmf * area.pdf(x_image, p, ng));
}

// What a path carries from one vertex to the next, besides the vertex itself.
template <class T>
struct PathState {
  SensorStokes L{};
  SampledSpectrum* groups = nullptr;  // light groups (LightSink)
  float group_weight = 1.0f;
  T beta;
  bool specular = true;  // the previous event was the camera or a delta lobe: no MIS on emission
  float prev_pdf = 0.0f;
  Vec3 prev_p{};
  // The last vertex was a planar mirror reached from a non-delta vertex x (position, BSDF pdf): emission
  // found next could also have been sampled through the mirror (mirrored_light).
  int chain_mirror = -1;
  float chain_pdf = 0.0f;
  Vec3 chain_origin{};
  // The lights' probabilities at the last vertex that sampled a light, when they depend on the point.
  Scene::LightPmfs light_pmfs{};
  Ray ray;
  float path_length = 0.0f;  // along the path so far, for the texture footprint
};

template <class Sampler, class T>
bool PathIntegrator::arrive(PathState<T>& s, PathVertex& v, uint32_t depth, const RayCone& cone,
                            const SampledWavelengths& lambda, const Sampler& sampler, LobeArena& arena,
                            size_t arena_floor, bool own_lobes, PathStats& stats, FirstHit* first_hit) const {
  const auto light_pmf = [&](int light) { return light_choice_pmf(light, s.light_pmfs); };
  ++stats.rays;
  const auto hit = scene_.accel->intersect(s.ray);
  if (!hit) {
    if (scene_.environment) {
      // After the camera or a delta lobe the environment could not have been sampled: no MIS, and no
      // pdf lookup (one cache miss fewer for rays that see the sky directly).
      float env_pdf = 0.0f;
      const SampledSpectrum Le = s.specular ? scene_.environment->radiance(s.ray.dir, lambda)
                                            : scene_.environment->radiance(s.ray.dir, lambda, &env_pdf);
      const float w =
          s.specular ? 1.0f : power_heuristic(s.prev_pdf, light_pmf(scene_.environment_light) * env_pdf);
      deliver(LightSink{s.L, s.groups, s.group_weight}, group_of(scene_.environment_light),
              [&](SensorStokes& L) {
                s.beta.receive(IncomingLight{Le * w, false, {}}, -s.ray.dir, L);
              });
    }
    return false;
  }

  const Mesh& mesh = scene_.meshes[hit->mesh];
  // A path's last vertex only adds what it emits: where its material cannot emit, neither the hit's
  // geometry nor its material is needed (the same image; most paths of a dark, closed scene such as the
  // cave reach max_depth, so this is about one shading point in five there).
  if (depth >= max_depth_ && !scene_.materials[mesh.material]->facts().is_emissive) return false;
  v.sp = surface_point(scene_.meshes, *hit, s.ray);
  // The guide's cell loads while the material is evaluated.
  const ptrdiff_t guide_cell = guide_ ? guide_->prefetch(v.sp.p) : -1;
  v.mesh = hit->mesh;
  const Vec3 wo = -s.ray.dir;
  arena.reset(arena_floor);  // v.closure is replaced below (CompiledMaterial::evaluate, evaluate_memoized)
  s.path_length += hit->t * length(s.ray.dir);
  ShadingContext ctx = shading_context(v.sp, scene_.origin.to_float(), lambda, scene_.textures.get(), &mesh);
  // The camera's cone carried along the path (pbrt-v4 approximates later hits the same way); in uv
  // units through the triangle's world-per-uv scale.
  ctx.footprint = cone.width_at(s.path_length);
  if (v.sp.area_scale_uv > 0.0f) ctx.uv_footprint = ctx.footprint / std::sqrt(v.sp.area_scale_uv);
  if (own_lobes)
    scene_.materials[mesh.material]->evaluate(ctx, arena, v.closure);
  else
    evaluate_memoized(*scene_.materials[mesh.material], ctx, arena, v.closure);

  // Emission seen by this path segment (one-sided: front face only).
  if (!v.closure.emission().is_black() && dot(v.sp.ng, wo) > 0.0f) {
    float w = 1.0f;
    const int light = scene_.mesh_light[hit->mesh];
    if (!s.specular && light >= 0) {
      const auto& area = static_cast<const AreaLight&>(*scene_.lights[light]);
      w = power_heuristic(s.prev_pdf, light_pmf(light) * area.pdf(s.prev_p, v.sp.p, v.sp.ng));
    } else if (s.chain_mirror >= 0 && light >= 0) {
      w = mirrored_emission_weight(s.chain_mirror, light, s.chain_origin, s.chain_pdf, v.sp.p, v.sp.ng);
    }
    const std::optional<Vec3> polarizer = light >= 0 ? scene_.lights[light]->polarizer_axis : std::nullopt;
    deliver(LightSink{s.L, s.groups, s.group_weight}, group_of(light), [&](SensorStokes& L) {
      s.beta.receive(filtered_emission(polarizer, wo, v.closure.emission() * w), wo, L);
    });
  }
  if (depth >= max_depth_ || !v.closure.has_lobes()) return false;

  const bool refracts = v.closure.has_transmission();
  v.ng = refracts || dot(v.sp.ng, wo) >= 0.0f ? v.sp.ng : -v.sp.ng;
  v.frame = shading_frame(v.sp, v.ng, wo, refracts, v.closure);
  v.wo_local = v.frame.to_local(wo);
  v.guided = false;
  // Specular and refracting closures are not guided: the guide's cosine is taken on the frame's side.
  if (guide_ && !v.closure.has_delta_lobes() && !v.closure.has_transmission())
    if (const PathGuide::Cell* cell = guide_->usable_cell(guide_cell))
      v.guided = PathGuide::product(*cell, v.frame.n, &v.guide);
  if (depth == 0 && first_hit) record_first_hit(v, hit->t * length(s.ray.dir), lambda, *first_hit);

  if (v.closure.has_non_delta_lobes() && !scene_.lights.empty()) {
    if (local_lights_) scene_.light_pmfs(v.sp.p, s.light_pmfs);
    const LightSink sink{s.L, s.groups, s.group_weight};
    direct_light(v, wo, s.beta, lambda, sampler, depth, local_lights_ ? &s.light_pmfs : nullptr, stats, sink);
    if (!scene_.mirror_lights.empty() && depth + 2 <= max_depth_)
      mirrored_light(v, wo, s.beta, lambda, sampler, depth, arena, stats, sink);
  }
  return true;
}

float PathIntegrator::scatter_pdf(const PathVertex& v, const Vec3& wi_local, const Vec3& wi,
                                  const SampledWavelengths& lambda) const {
  const float bsdf = v.closure.pdf(v.wo_local, wi_local, lambda);
  if (!v.guided) return bsdf;
  return PathGuide::kGuideShare * PathGuide::pdf(v.guide, wi) + (1.0f - PathGuide::kGuideShare) * bsdf;
}

template <class T>
bool PathIntegrator::guided_scatter(PathState<T>& s, const PathVertex& v, const Vec3& wo, float u_lobe,
                                    const Vec2& u, const SampledWavelengths& lambda, Vec3& wi,
                                    float& pdf) const {
  // One-sample MIS of the guide and the BSDF (path_guide.h): u_lobe picks the strategy, then is reused
  // (rescaled) for the guide's bin or the BSDF's lobe; either way the weight is f |cos| / the mixture pdf.
  const float share = PathGuide::kGuideShare;
  if (u_lobe < share) {
    float guide_pdf = 0.0f;
    wi = PathGuide::sample(v.guide, u_lobe / share, u, &guide_pdf);
    const Vec3 wi_local = v.frame.to_local(wi);
    if (dot(wi, v.ng) * wi_local.z <= 0.0f) return false;  // shading and geometric sides disagree
    std::optional<MuellerResponse> storage;
    const WorldResponse r = vertex_response<T>(v, wo, wi_local, lambda, storage);
    if (r.f.is_black()) return false;
    pdf = share * guide_pdf + (1.0f - share) * v.closure.pdf(v.wo_local, wi_local, lambda);
    if (!(pdf > 0.0f)) return false;
    const float k = abs_cos_theta(wi_local) / pdf;
    if (r.m) storage->m = storage->m * k;
    s.beta.scatter(r, r.f * k);
    return true;
  }
  auto bs =
      v.closure.sample(v.wo_local, std::min((u_lobe - share) / (1.0f - share), 0x1.fffffep-1f), u, lambda);
  if (!bs || bs->weight.is_black() || bs->delta) return false;
  wi = v.frame.to_world(bs->wi);
  if (dot(wi, v.ng) * bs->wi.z <= 0.0f) return false;
  pdf = share * PathGuide::pdf(v.guide, wi) + (1.0f - share) * bs->pdf;
  const float k = bs->pdf / pdf;  // from the BSDF's weight f |cos| / pdf_bsdf to f |cos| / the mixture's
  const WorldResponse r = sampled_response<T>(v, wo, *bs, lambda);  // r.m is bs->mueller.m, if any
  if (r.m) bs->mueller.m = bs->mueller.m * k;
  s.beta.scatter(r, bs->weight * k);
  return true;
}

template <class Sampler, class T>
bool PathIntegrator::scatter(PathState<T>& s, const PathVertex& v, uint32_t depth,
                             const SampledWavelengths& lambda, const Sampler& sampler) const {
  // The vertex this bounce would reach, at max_depth, adds only the emission it finds (arrive), and in a
  // scene where no ray can find light there is none: the same image, with a ray and a BSDF sample fewer per
  // path.
  if (depth + 1 >= max_depth_ && !last_bounce_finds_light_) return false;
  const Vec3 wo = -s.ray.dir;
  const float u_lobe = sampler.get_1d(SampleDims::bounce(depth, SampleDims::kLobeChoice));
  const Vec2 u_direction = sampler.get_2d(SampleDims::bounce(depth, SampleDims::kLobeDirection));
  Vec3 wi;
  float pdf = 0.0f;
  bool delta = false;
  if (v.guided) {
    if (!guided_scatter(s, v, wo, u_lobe, u_direction, lambda, wi, pdf)) return false;
  } else {
    auto bs = v.closure.sample(v.wo_local, u_lobe, u_direction, lambda);
    if (!bs || bs->weight.is_black()) return false;
    wi = v.frame.to_world(bs->wi);
    if (dot(wi, v.ng) * bs->wi.z <= 0.0f) return false;  // shading and geometric sides disagree: no leaks
    s.beta.scatter(sampled_response<T>(v, wo, *bs, lambda), bs->weight);
    pdf = bs->pdf;
    delta = bs->delta;
  }
  s.chain_mirror = delta && !s.specular ? scene_.mirror_lights.mirror_of_mesh(v.mesh) : -1;
  s.chain_pdf = s.prev_pdf;
  s.chain_origin = s.prev_p;
  s.specular = delta;
  s.prev_pdf = pdf;
  s.prev_p = v.sp.p;

  // Russian roulette on the path throughput's unpolarized part M00, with survival probability
  // sqrt(max M00) (Cycles' rule; pbrt's max M00 terminates more often): per-path quantities only, so
  // renders stay deterministic. From rr_depth (default 5, as Mitsuba) on: terminating earlier costs
  // more variance than it saves time, most of all on caustic paths (docs/performance.md, "Time to
  // error against Cycles").
  if (depth + 1 >= rr_depth_) {
    const float survival = std::sqrt(s.beta.m00().max_value());
    if (survival < 1.0f) {
      if (sampler.get_1d(SampleDims::bounce(depth, SampleDims::kRoulette)) >= survival) return false;
      s.beta.scale(1.0f / survival);
    }
  }
  s.ray = spawn_ray(v.sp, v.ng, wi);
  return true;
}

template <class Sampler, class T>
bool PathIntegrator::trace_shared(PathState<T>& s, PathVertex& v, uint32_t& depth, const RayCone& cone,
                                  const SampledWavelengths& lambda, const Sampler& sampler, LobeArena& arena,
                                  PathStats& stats, FirstHit* first_hit) const {
  if (!arrive(s, v, 0, cone, lambda, sampler, arena, 0, true, stats, first_hit)) return false;
  // Usually the first vertex; a mirror or glass seen by the camera would hand every branch the same
  // direction.
  for (depth = 0; !v.closure.has_non_delta_lobes(); ++depth)
    if (!scatter(s, v, depth, lambda, sampler) ||
        !arrive(s, v, depth + 1, cone, lambda, sampler, arena, 0, true, stats, nullptr))
      return false;
  return true;
}

template <class Sampler, class T>
SensorStokes PathIntegrator::continue_branch(const PathState<T>& shared, const PathVertex& v, uint32_t depth,
                                             uint32_t j, uint32_t k, const RayCone& cone,
                                             const SampledWavelengths& lambda, const Sampler& sampler,
                                             LobeArena& arena, size_t floor, PathStats& stats) const {
  const Sampler numbers = sampler.branch(j, k);
  PathState<T> c = shared;
  c.L = SensorStokes{};
  c.group_weight = 1.0f / static_cast<float>(k);
  PathVertex w;
  for (uint32_t d = depth; scatter(c, d == depth ? v : w, d, lambda, numbers); ++d)
    if (!arrive(c, w, d + 1, cone, lambda, numbers, arena, floor, false, stats, nullptr)) break;
  return c.L;
}

template <class T>
PathState<T> PathIntegrator::camera_state(const Ray& camera_ray, SampledSpectrum* groups) const {
  return PathState<T>{.groups = groups,
                      .beta = T(scene_.camera_analyzer ? &*scene_.camera_analyzer : nullptr,
                                T::kPolarized ? camera_stokes_axis(scene_.camera, camera_ray.dir) : Vec3{}),
                      .ray = camera_ray};
}

template <class Sampler, class T>
SensorStokes PathIntegrator::trace(const Ray& camera_ray, const RayCone& cone,
                                   const SampledWavelengths& lambda, const Sampler& sampler, LobeArena& arena,
                                   PathStats& stats, FirstHit* first_hit, SampledSpectrum* groups) const {
  PathState<T> s = camera_state<T>(camera_ray, groups);
  PathVertex v;
  if (branches_ == 1) {
    if (!arrive(s, v, 0, cone, lambda, sampler, arena, 0, false, stats, first_hit)) return s.L;
    for (uint32_t depth = 0; scatter(s, v, depth, lambda, sampler); ++depth)
      if (!arrive(s, v, depth + 1, cone, lambda, sampler, arena, 0, false, stats, nullptr)) break;
    return s.L;
  }
  // Branched path tracing (docs/architecture.md#branched-paths): the path up to its first vertex with a
  // non-delta lobe is shared by `branches_` continuations, each with its own numbers (Sampler::branch),
  // averaged. The shared vertex's lobes stay in the arena (evaluated outside the per-thread memo, which a
  // later vertex could overwrite) while the branches reuse the space above.
  uint32_t depth = 0;
  if (!trace_shared(s, v, depth, cone, lambda, sampler, arena, stats, first_hit)) return s.L;
  const size_t floor = arena.used();
  SensorStokes sum{};
  for (uint32_t j = 0; j < branches_; ++j) {
    const SensorStokes c =
        continue_branch(s, v, depth, j, branches_, cone, lambda, sampler, arena, floor, stats);
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += c[i];
  }
  const float inv = 1.0f / static_cast<float>(branches_);
  for (size_t i = 0; i < sum.size(); ++i) s.L[i] += sum[i] * inv;
  return s.L;
}

template <class Sampler, class T>
BranchPilotSample PathIntegrator::pilot_trace(const Ray& camera_ray, const RayCone& cone,
                                              const SampledWavelengths& lambda, const Sampler& sampler,
                                              LobeArena& arena) const {
  BranchPilotSample out;
  PathStats stats;
  PathState<T> s = camera_state<T>(camera_ray, nullptr);
  PathVertex v;
  uint32_t depth = 0;
  out.branched = trace_shared(s, v, depth, cone, lambda, sampler, arena, stats, nullptr);
  out.shared = s.L[0];
  out.shared_rays = stats.rays;
  out.shared_shadow_rays = stats.shadow_rays;
  if (!out.branched) return out;
  const size_t floor = arena.used();
  for (uint32_t j = 0; j < out.branch.size(); ++j) {
    PathStats branch_stats;
    out.branch[j] = continue_branch(s, v, depth, j, 2, cone, lambda, sampler, arena, floor, branch_stats)[0];
    out.branch_rays += branch_stats.rays;
    out.branch_shadow_rays += branch_stats.shadow_rays;
  }
  return out;
}

template <class Sampler, class T>
void PathIntegrator::record_training_path(const Ray& camera_ray, const RayCone& cone,
                                          const SampledWavelengths& lambda, const Sampler& sampler,
                                          LobeArena& arena, std::vector<GuideRecord>& out) const {
  // Each scattering: where, which way, with what density, the throughput after it and the light gathered
  // before it. What the path gathers after a scattering, over the throughput, is the light that arrived
  // along that direction (its MIS-weighted share of emission found there included).
  struct Scattering {
    Vec3 p, dir;
    float pdf;
    SampledSpectrum beta, before;
  };
  constexpr int kMaxScatterings = 16;
  std::array<Scattering, kMaxScatterings> open;
  int n = 0;
  PathStats stats;
  PathState<T> s = camera_state<T>(camera_ray, nullptr);
  PathVertex v;
  if (!arrive(s, v, 0, cone, lambda, sampler, arena, 0, false, stats, nullptr)) return;
  for (uint32_t depth = 0; scatter(s, v, depth, lambda, sampler); ++depth) {
    if (n < kMaxScatterings && !s.specular) open[n++] = {v.sp.p, s.ray.dir, s.prev_pdf, s.beta.m00(), s.L[0]};
    if (!arrive(s, v, depth + 1, cone, lambda, sampler, arena, 0, false, stats, nullptr)) break;
  }
  for (int i = 0; i < n; ++i) {
    const Scattering& o = open[i];
    float sum = 0.0f;
    int lanes = 0;
    for (int l = 0; l < kSpectrumSamples; ++l) {
      if (!(o.beta[l] > 0.0f)) continue;
      sum += (s.L[0][l] - o.before[l]) / o.beta[l];
      ++lanes;
    }
    if (lanes > 0) out.push_back({o.p, o.dir, std::max(sum / static_cast<float>(lanes), 0.0f), o.pdf});
  }
}

template <class Sampler>
void PathIntegrator::guide_training_path(const Ray& ray, const RayCone& cone,
                                         const SampledWavelengths& lambda, const Sampler& sampler,
                                         LobeArena& arena, std::vector<GuideRecord>& out) const {
  with_throughput(
      [&]<class T>() { record_training_path<Sampler, T>(ray, cone, lambda, sampler, arena, out); });
}

template <class Traced>
auto PathIntegrator::with_throughput(const Traced& traced) const {
  switch (mode_) {
    case PolarizationMode::kIntensity:
      return traced.template operator()<IntensityThroughput>();
    case PolarizationMode::kStokes:
      return traced.template operator()<StokesThroughput>();
    case PolarizationMode::kOff:
      break;
  }
  return traced.template operator()<UnpolarizedThroughput>();
}

template <class Sampler>
BranchPilotSample PathIntegrator::pilot_sample(const Ray& ray, const RayCone& cone,
                                               const SampledWavelengths& lambda, const Sampler& sampler,
                                               LobeArena& arena) const {
  return with_throughput(
      [&]<class T>() { return pilot_trace<Sampler, T>(ray, cone, lambda, sampler, arena); });
}

template <class Sampler>
SensorStokes PathIntegrator::radiance(const Ray& ray, const RayCone& cone, const SampledWavelengths& lambda,
                                      const Sampler& sampler, LobeArena& arena, PathStats& stats,
                                      FirstHit* first_hit, SampledSpectrum* groups) const {
  return with_throughput([&]<class T>() {
    return trace<Sampler, T>(ray, cone, lambda, sampler, arena, stats, first_hit, groups);
  });
}

template SensorStokes PathIntegrator::radiance(const Ray&, const RayCone&, const SampledWavelengths&,
                                               const IndependentSampler&, LobeArena&, PathStats&, FirstHit*,
                                               SampledSpectrum*) const;
template SensorStokes PathIntegrator::radiance(const Ray&, const RayCone&, const SampledWavelengths&,
                                               const SobolSampler&, LobeArena&, PathStats&, FirstHit*,
                                               SampledSpectrum*) const;

template BranchPilotSample PathIntegrator::pilot_sample(const Ray&, const RayCone&, const SampledWavelengths&,
                                                        const IndependentSampler&, LobeArena&) const;
template void PathIntegrator::guide_training_path(const Ray&, const RayCone&, const SampledWavelengths&,
                                                  const IndependentSampler&, LobeArena&,
                                                  std::vector<GuideRecord>&) const;
template BranchPilotSample PathIntegrator::pilot_sample(const Ray&, const RayCone&, const SampledWavelengths&,
                                                        const SobolSampler&, LobeArena&) const;

}  // namespace ochre
