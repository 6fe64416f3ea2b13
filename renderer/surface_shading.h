#pragma once
// The ShadingContext a material graph sees at a surface point.

#include "materials/nodes/shading_context.h"
#include "renderer/accel.h"

namespace ochre {

inline ShadingContext shading_context(const SurfacePoint& sp, const SampledWavelengths& lambda,
                                      const TextureProvider* textures, const Mesh* mesh = nullptr) {
  ShadingContext ctx;
  ctx.p = sp.p;
  ctx.n = sp.ns;
  ctx.uv = sp.uv;
  ctx.dpdu = sp.dpdu;
  if (mesh) ctx.object_axes = mesh->object_axes.data();
  if (sp.has_colour) ctx.vertex_colour = {sp.colour.x, sp.colour.y, sp.colour.z};
  ctx.lambda = &lambda;
  ctx.textures = textures;
  return ctx;
}

}  // namespace ochre
