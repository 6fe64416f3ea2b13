#pragma once
// ShadingContext: what a material graph may read at a shading point.

#include "materials/core/vec3.h"
#include "materials/nodes/non_finite_tally.h"
#include "materials/nodes/texture_provider.h"
#include "spectra/color_types.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

struct ShadingContext {
  Vec3 p;                      // world position
  Vec3 n;                      // shading normal (world)
  Vec2 uv;                     // mesh texture coordinates (0,0 when the mesh has none)
  RGB vertex_colour{1, 1, 1};  // linear Rec.709, (1,1,1) when the mesh has none
  Vec3 dpdu{1, 0, 0};          // world tangent along increasing u (an arbitrary tangent without UVs)
  // The object's x, y and z axes in world space (the linear part of the object-to-world transform,
  // 3 vectors), or null for the identity.
  const Vec3* object_axes = nullptr;
  float uv_footprint = 0;  // texture filter width in uv units (0 = point lookup)
  float footprint = 0;     // the same width in world units (0 = point lookup), for computed coordinates
  const SampledWavelengths* lambda = nullptr;
  const TextureProvider* textures = nullptr;
  NonFiniteTally* nonfinite = nullptr;  // counts the NaN / infinite values made finite (null: not counted)
};

}  // namespace ochre
