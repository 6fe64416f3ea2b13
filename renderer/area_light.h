#pragma once
// Area light: a mesh whose material emits. Points are sampled uniformly by area; emission is
// one-sided (front face = counter-clockwise winding) and comes from the material graph, so
// textured and spectral emission work the same as in camera rays.

#include "materials/compiled_material.h"
#include "materials/texture_provider.h"
#include "renderer/accel.h"
#include "renderer/distribution_1d.h"
#include "renderer/light.h"
#include "renderer/mesh.h"

namespace ochre {

class AreaLight final : public Light {
 public:
  AreaLight(const Mesh& mesh, const CompiledMaterial& material, const TextureProvider* textures);
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override { return power_; }

  // Solid-angle pdf of sampling point p (normal ng) from ref, given the point is on this light.
  float pdf(const Vec3& ref, const Vec3& p, const Vec3& ng) const;
  // Emitted radiance at a point toward `to_viewer` (0 on the back side).
  SampledSpectrum emitted(const SurfacePoint& sp, const Vec3& to_viewer,
                          const SampledWavelengths& lambda) const;

 private:
  const Mesh& mesh_;
  const CompiledMaterial& material_;
  const TextureProvider* textures_;
  Distribution1D triangles_;
  float total_area_ = 0.0f;
  float power_ = 0.0f;
};

}  // namespace ochre
