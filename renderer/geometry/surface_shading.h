#pragma once
// The ShadingContext a material graph sees at a surface point.

#include "materials/nodes/shading_context.h"
#include "renderer/geometry/accel.h"

namespace ochre {

// The tally of NaN / infinite values this thread's material evaluations made finite
// (materials/nodes/non_finite_tally.h); render() adds each tile's increase to RenderStats::nonfinite_values.
inline NonFiniteTally& thread_non_finite_tally() {
  thread_local NonFiniteTally tally;
  return tally;
}

// `origin`: the rendering origin (renderer/scene/scene.h); the material sees the world position origin + p.
inline ShadingContext shading_context(const SurfacePoint& sp, const Vec3& origin,
                                      const SampledWavelengths& lambda, const TextureProvider* textures,
                                      const Mesh* mesh = nullptr) {
  ShadingContext ctx;
  ctx.p = sp.p + origin;
  ctx.n = sp.ns;
  ctx.uv = sp.uv;
  ctx.dpdu = sp.dpdu;
  if (mesh) ctx.object_axes = mesh->object_axes.data();
  if (sp.has_colour) ctx.vertex_colour = {sp.colour.x, sp.colour.y, sp.colour.z};
  ctx.lambda = &lambda;
  ctx.textures = textures;
  ctx.nonfinite = &thread_non_finite_tally();
  return ctx;
}

}  // namespace ochre
