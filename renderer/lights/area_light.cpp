#include "renderer/lights/area_light.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "materials/core/sampling.h"
#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "renderer/geometry/surface_shading.h"
#include "spectra/cie.h"
#include "spectra/tabulated_spectrum.h"
#include "spectra/wavelength_memo.h"

namespace ochre {

namespace {

// Fixed wavelength sets used to estimate a light's power (deterministic, no sampling noise).
float luminance_estimate(const std::function<SampledSpectrum(const SampledWavelengths&)>& radiance) {
  float y = 0.0f;
  constexpr int kSets = 16;
  for (int k = 0; k < kSets; ++k) {
    const SampledWavelengths lambda = SampledWavelengths::sample_visible((k + 0.5f) / kSets);
    const XYZ xyz = sampled_to_xyz(radiance(lambda), lambda);
    y += xyz.y;
  }
  return y / kSets;
}

}  // namespace

AreaLight::AreaLight(const Mesh& mesh, const CompiledMaterial& material, const TextureProvider* textures,
                     const Vec3& origin)
    : mesh_(mesh),
      material_(material),
      textures_(textures),
      origin_(origin),
      memo_key_(new_wavelength_memo_key()) {
  std::vector<double> areas(mesh.triangle_count());
  for (size_t i = 0; i < areas.size(); ++i) areas[i] = mesh.triangle_area(i);
  triangles_ = Distribution1D(areas);
  normals_.resize(areas.size());
  for (size_t i = 0; i < areas.size(); ++i) normals_[i] = triangle_normal(mesh, static_cast<uint32_t>(i));
  total_area_ = static_cast<float>(triangles_.total());

  // Power: area-weighted emission at the centroids of up to 64 triangles, times pi (Lambertian emitter).
  const size_t n = mesh.triangle_count();
  const size_t step = std::max<size_t>(1, n / 64);
  double weighted = 0.0, area = 0.0;
  for (size_t i = 0; i < n; i += step) {
    const SurfacePoint t = surface_point(mesh, static_cast<uint32_t>(i), 1.0f / 3.0f, 1.0f / 3.0f);
    const float y =
        luminance_estimate([&](const SampledWavelengths& lambda) { return emitted(t, t.ng, lambda); });
    weighted += y * areas[i];
    area += areas[i];
  }
  power_ = area > 0.0 ? static_cast<float>(kPi * total_area_ * weighted / area) : 0.0f;

  if (!mesh.positions.empty()) {
    const Mesh::Bounds b = mesh.bounds();
    bound_center_ = (b.lo + b.hi) * 0.5f;
    bound_radius2_ = length_squared(b.hi - b.lo) * 0.25f;
  }
  mean_radiance_ = total_area_ > 0.0f ? power_ / (kPi * total_area_) : 0.0f;
}

const Spectrum* AreaLight::emission_spectrum() const {
  std::call_once(emission_once_, [&] {
    if (material_.facts().uniform_over_surface) emission_ = uniform_emission_spectrum();
  });
  return emission_.get();
}

SpectrumPtr AreaLight::uniform_emission_spectrum() const {
  // The emission at every nm of 360..830 (the grid of spectra/emission_shape.h), read as linear between.
  std::vector<float> lambda, values;
  for (int nm = 360; nm <= 830; ++nm) {
    const SampledWavelengths at = SampledWavelengths::fixed(SampledSpectrum(static_cast<float>(nm)));
    lambda.push_back(static_cast<float>(nm));
    values.push_back(std::max(0.0f, evaluate_emission(SurfacePoint{}, at)[0]));  // negative emits nothing
  }
  return std::make_shared<TabulatedSpectrum>(std::move(lambda), std::move(values));
}

float AreaLight::importance(const Vec3& p) const {
  // Mean radiance times the solid angle the light can subtend (its area over the squared distance beyond its
  // bounding sphere), at most a hemisphere's pi.
  const float d2 = length_squared(p - bound_center_) - bound_radius2_;
  return mean_radiance_ * (d2 > total_area_ / kPi ? total_area_ / d2 : kPi);
}

SampledSpectrum AreaLight::emitted(const SurfacePoint& sp, const Vec3& to_viewer,
                                   const SampledWavelengths& lambda) const {
  if (dot(sp.ng, to_viewer) <= 0.0f) return SampledSpectrum(0.0f);
  return material_.facts().uniform_over_surface ? uniform_emission(lambda) : evaluate_emission(sp, lambda);
}

SampledSpectrum AreaLight::evaluate_emission(const SurfacePoint& sp, const SampledWavelengths& lambda) const {
  thread_local LobeArena arena;  // the default size holds kMaxLobes of the largest lobe
  arena.reset();
  Closure closure;
  material_.evaluate(shading_context(sp, origin_, lambda, textures_), arena, closure);
  return closure.emission();
}

// Memoized per thread for the path's wavelengths (spectra/wavelength_memo.h), keyed by the light's memo key.
SampledSpectrum AreaLight::uniform_emission(const SampledWavelengths& lambda) const {
  return memo_sampled(memo_key_, lambda,
                      [&] { return evaluate_emission(SurfacePoint{}, lambda); });  // reads no point
}

std::optional<LightSample> AreaLight::sample(const Vec3& ref, const Vec2& u,
                                             const SampledWavelengths& lambda) const {
  if (total_area_ <= 0.0f) return std::nullopt;
  float u_tri = 0.0f;
  const size_t tri = triangles_.sample(u.x, &u_tri);
  const Vec2 b = sample_uniform_triangle({u_tri, u.y});
  // Position and normal are all a uniform emitter needs; a textured one gets the whole shading point.
  const Vec3& ng = normals_[tri];
  if (dot(ng, ng) == 0.0f) return std::nullopt;

  const Vec3 d = triangle_position(mesh_, static_cast<uint32_t>(tri), b.x, b.y) - ref;
  const float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return std::nullopt;
  LightSample s;
  s.distance = std::sqrt(dist2);
  s.wi = d / s.distance;
  const float cos_light = -dot(ng, s.wi);
  if (cos_light <= 0.0f) return std::nullopt;  // back side: one-sided emitter
  s.pdf = dist2 / (cos_light * total_area_);   // area pdf 1/A converted to solid angle
  s.radiance = material_.facts().uniform_over_surface
                   ? uniform_emission(lambda)
                   : evaluate_emission(surface_point(mesh_, static_cast<uint32_t>(tri), b.x, b.y), lambda);
  s.light_normal = ng;
  return s;
}

float AreaLight::pdf(const Vec3& ref, const Vec3& p, const Vec3& ng) const {
  const Vec3 d = p - ref;
  const float dist2 = dot(d, d);
  const float cos_light = std::fabs(dot(normalize(ng), d)) / std::sqrt(dist2);
  if (!(cos_light > 0.0f) || total_area_ <= 0.0f) return 0.0f;
  return dist2 / (cos_light * total_area_);
}

}  // namespace ochre
