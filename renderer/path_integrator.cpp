#include "renderer/path_integrator.h"

#include <cmath>

#include "materials/closure.h"
#include "materials/frame.h"
#include "materials/sampling.h"
#include "renderer/surface_shading.h"

namespace ochre {

// One scattering vertex of a path: geometry, shading frame and the evaluated closure.
struct PathVertex {
  SurfacePoint sp;
  Vec3 ng;  // unit geometric normal on the side of wo
  Frame frame;
  Vec3 wo_local;
  Closure closure;
};

namespace {

// Shading frame around the interpolated normal, flipped to the viewer's side of the surface.
// Falls back to the geometric normal where the shading normal hides the viewer.
Frame shading_frame(const SurfacePoint& sp, const Vec3& ng, const Vec3& wo) {
  Vec3 ns = sp.ns;
  if (dot(ns, ng) < 0.0f) ns = -ns;
  if (dot(ns, wo) <= 0.0f) ns = ng;
  return Frame::from_normal(ns);
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

}  // namespace

template <class Sampler>
SampledSpectrum PathIntegrator::direct_light(const PathVertex& v, const SampledWavelengths& lambda,
                                             const Sampler& sampler, uint32_t depth, PathStats& stats) const {
  float u_light = 0.0f;
  const size_t index = scene_.light_selection.sample(
      sampler.get_1d(SampleDims::bounce(depth, SampleDims::kLightChoice)), &u_light);
  const float pmf = scene_.light_selection.pmf(index);
  if (!(pmf > 0.0f)) return SampledSpectrum(0.0f);
  const Light& light = *scene_.lights[index];
  const auto ls =
      light.sample(v.sp.p, sampler.get_2d(SampleDims::bounce(depth, SampleDims::kLightPosition)), lambda);
  if (!ls || !(ls->pdf > 0.0f) || ls->radiance.is_black()) return SampledSpectrum(0.0f);
  if (dot(ls->wi, v.ng) <= 0.0f) return SampledSpectrum(0.0f);  // reflection lobes only see the front side

  const Vec3 wi_local = v.frame.to_local(ls->wi);
  const SampledSpectrum f = v.closure.eval(v.wo_local, wi_local, lambda) * abs_cos_theta(wi_local);
  if (f.is_black()) return SampledSpectrum(0.0f);

  Ray shadow;
  shadow.origin = offset_ray_origin(v.sp.p, v.ng, ls->wi);
  shadow.dir = ls->wi;
  shadow.tmax = std::isinf(ls->distance) ? INFINITY : ls->distance * (1.0f - 1e-4f);
  ++stats.shadow_rays;
  if (scene_.accel->occluded(shadow)) return SampledSpectrum(0.0f);

  const float light_pdf = pmf * ls->pdf;
  if (ls->delta) return f * ls->radiance / light_pdf;
  const float bsdf_pdf = v.closure.pdf(v.wo_local, wi_local, lambda);
  return f * ls->radiance * (power_heuristic(light_pdf, bsdf_pdf) / light_pdf);
}

template <class Sampler>
SampledSpectrum PathIntegrator::radiance(const Ray& camera_ray, const RayCone& cone,
                                         const SampledWavelengths& lambda, const Sampler& sampler,
                                         LobeArena& arena, PathStats& stats, FirstHit* first_hit) const {
  const RenderSettings& settings = scene_.settings;
  SampledSpectrum L(0.0f), beta(1.0f);
  bool specular = true;  // the previous event was the camera or a delta lobe: no MIS on emission
  float prev_pdf = 0.0f;
  Vec3 prev_p;
  Ray ray = camera_ray;
  float path_length = 0.0f;  // along the path so far, for the texture footprint
  PathVertex v;

  for (uint32_t depth = 0;; ++depth) {
    ++stats.rays;
    const auto hit = scene_.accel->intersect(ray);
    if (!hit) {
      if (scene_.environment) {
        float w = 1.0f;
        if (!specular) {
          const float light_pdf =
              scene_.light_pmf(scene_.environment_light) * scene_.environment->pdf(ray.dir);
          w = power_heuristic(prev_pdf, light_pdf);
        }
        L += beta * scene_.environment->radiance(ray.dir, lambda) * w;
      }
      break;
    }

    v.sp = surface_point(scene_.meshes, *hit, ray);
    const Vec3 wo = -ray.dir;
    const Mesh& mesh = scene_.meshes[hit->mesh];
    arena.reset();
    v.closure = Closure();
    path_length += hit->t * length(ray.dir);
    ShadingContext ctx = shading_context(v.sp, lambda, scene_.textures.get());
    // The camera's cone carried along the path (pbrt-v4 approximates later hits the same way); in uv
    // units through the triangle's world-per-uv scale.
    if (v.sp.area_scale_uv > 0.0f)
      ctx.uv_footprint = cone.width_at(path_length) / std::sqrt(v.sp.area_scale_uv);
    scene_.materials[mesh.material]->evaluate(ctx, arena, v.closure);

    // Emission seen by this path segment (one-sided: front face only).
    if (!v.closure.emission().is_black() && dot(v.sp.ng, wo) > 0.0f) {
      float w = 1.0f;
      const int light = scene_.mesh_light[hit->mesh];
      if (!specular && light >= 0) {
        const auto& area = static_cast<const AreaLight&>(*scene_.lights[light]);
        w = power_heuristic(prev_pdf, scene_.light_pmf(light) * area.pdf(prev_p, v.sp.p, v.sp.ng));
      }
      L += beta * v.closure.emission() * w;
    }
    if (depth >= static_cast<uint32_t>(settings.max_depth) || !v.closure.has_lobes()) break;

    v.ng = dot(v.sp.ng, wo) < 0.0f ? -v.sp.ng : v.sp.ng;
    v.frame = shading_frame(v.sp, v.ng, wo);
    v.wo_local = v.frame.to_local(wo);
    if (depth == 0 && first_hit) record_first_hit(v, hit->t * length(ray.dir), lambda, *first_hit);

    if (v.closure.has_non_delta_lobes() && !scene_.lights.empty())
      L += beta * direct_light(v, lambda, sampler, depth, stats);

    const auto bs =
        v.closure.sample(v.wo_local, sampler.get_1d(SampleDims::bounce(depth, SampleDims::kLobeChoice)),
                         sampler.get_2d(SampleDims::bounce(depth, SampleDims::kLobeDirection)), lambda);
    if (!bs || bs->weight.is_black()) break;
    const Vec3 wi = v.frame.to_world(bs->wi);
    if (dot(wi, v.ng) <= 0.0f) break;  // a reflection lobe must leave on the front side

    beta *= bs->weight;
    specular = bs->delta;
    prev_pdf = bs->pdf;
    prev_p = v.sp.p;

    // Russian roulette on the path throughput (pbrt's rule).
    if (depth + 1 >= static_cast<uint32_t>(settings.rr_depth)) {
      const float max_beta = beta.max_value();
      if (max_beta < 1.0f) {
        const float q = std::max(0.0f, 1.0f - max_beta);
        if (sampler.get_1d(SampleDims::bounce(depth, SampleDims::kRoulette)) < q) break;
        beta /= 1.0f - q;
      }
    }
    ray = Ray{offset_ray_origin(v.sp.p, v.ng, wi), wi};
  }
  return L;
}

template SampledSpectrum PathIntegrator::radiance(const Ray&, const RayCone&, const SampledWavelengths&,
                                                  const IndependentSampler&, LobeArena&, PathStats&,
                                                  FirstHit*) const;
template SampledSpectrum PathIntegrator::radiance(const Ray&, const RayCone&, const SampledWavelengths&,
                                                  const SobolSampler&, LobeArena&, PathStats&,
                                                  FirstHit*) const;

}  // namespace ochre
