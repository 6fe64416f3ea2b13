#include "renderer/area_light.h"

#include <cmath>
#include <functional>

#include "materials/closure.h"
#include "materials/lobe_arena.h"
#include "materials/sampling.h"
#include "materials/shading_context.h"
#include "spectra/cie.h"

namespace ochre {

namespace {

struct TrianglePoint {
  Vec3 p, ng, ns, colour{1, 1, 1};
  Vec2 uv;
};

TrianglePoint point_on_triangle(const Mesh& mesh, size_t tri, float b1, float b2) {
  const uint32_t i0 = mesh.indices[3 * tri], i1 = mesh.indices[3 * tri + 1], i2 = mesh.indices[3 * tri + 2];
  const float b0 = 1.0f - b1 - b2;
  TrianglePoint t;
  const Vec3 &p0 = mesh.positions[i0], &p1 = mesh.positions[i1], &p2 = mesh.positions[i2];
  t.p = p0 * b0 + p1 * b1 + p2 * b2;
  t.ng = normalize(cross(p1 - p0, p2 - p0));
  t.ns = t.ng;
  if (!mesh.normals.empty()) {
    const Vec3 n = mesh.normals[i0] * b0 + mesh.normals[i1] * b1 + mesh.normals[i2] * b2;
    if (length(n) > 0.0f) t.ns = normalize(n);
  }
  if (!mesh.uvs.empty()) {
    const Vec2 &a = mesh.uvs[i0], &b = mesh.uvs[i1], &c = mesh.uvs[i2];
    t.uv = {a.x * b0 + b.x * b1 + c.x * b2, a.y * b0 + b.y * b1 + c.y * b2};
  }
  if (!mesh.colours.empty()) t.colour = mesh.colours[i0] * b0 + mesh.colours[i1] * b1 + mesh.colours[i2] * b2;
  return t;
}

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

AreaLight::AreaLight(const Mesh& mesh, const CompiledMaterial& material, const TextureProvider* textures)
    : mesh_(mesh), material_(material), textures_(textures) {
  std::vector<double> areas(mesh.triangle_count());
  for (size_t i = 0; i < areas.size(); ++i) areas[i] = mesh.triangle_area(i);
  triangles_ = Distribution1D(areas);
  total_area_ = static_cast<float>(triangles_.total());

  // Power: area-weighted emission at the centroids of up to 64 triangles, times pi (Lambertian emitter).
  const size_t n = mesh.triangle_count();
  const size_t step = std::max<size_t>(1, n / 64);
  double weighted = 0.0, area = 0.0;
  for (size_t i = 0; i < n; i += step) {
    const TrianglePoint t = point_on_triangle(mesh, i, 1.0f / 3.0f, 1.0f / 3.0f);
    const float y = luminance_estimate([&](const SampledWavelengths& lambda) {
      return emitted(t.p, t.ng, t.ns, t.uv, t.colour, t.ng, lambda);
    });
    weighted += y * areas[i];
    area += areas[i];
  }
  power_ = area > 0.0 ? static_cast<float>(kPi * total_area_ * weighted / area) : 0.0f;
}

SampledSpectrum AreaLight::emitted(const Vec3& p, const Vec3& ng, const Vec3& ns, const Vec2& uv, const Vec3& colour,
                                   const Vec3& to_viewer, const SampledWavelengths& lambda) const {
  if (dot(ng, to_viewer) <= 0.0f) return SampledSpectrum(0.0f);
  thread_local LobeArena arena(4096);
  arena.reset();
  ShadingContext ctx;
  ctx.p = p;
  ctx.n = ns;
  ctx.uv = uv;
  ctx.vertex_colour = {colour.x, colour.y, colour.z};
  ctx.lambda = &lambda;
  ctx.textures = textures_;
  Closure closure;
  material_.evaluate(ctx, arena, closure);
  return closure.emission();
}

std::optional<LightSample> AreaLight::sample(const Vec3& ref, const Vec2& u, const SampledWavelengths& lambda) const {
  if (total_area_ <= 0.0f) return std::nullopt;
  float u_tri = 0.0f;
  const size_t tri = triangles_.sample(u.x, &u_tri);
  const Vec2 b = sample_uniform_triangle({u_tri, u.y});
  const TrianglePoint t = point_on_triangle(mesh_, tri, b.x, b.y);

  const Vec3 d = t.p - ref;
  const float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return std::nullopt;
  LightSample s;
  s.distance = std::sqrt(dist2);
  s.wi = d / s.distance;
  const float cos_light = -dot(t.ng, s.wi);
  if (cos_light <= 0.0f) return std::nullopt;  // back side: one-sided emitter
  s.pdf = dist2 / (cos_light * total_area_);    // area pdf 1/A converted to solid angle
  s.radiance = emitted(t.p, t.ng, t.ns, t.uv, t.colour, -s.wi, lambda);
  s.light_normal = t.ng;
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
