#pragma once
// Area light: a mesh whose material emits. Points are sampled uniformly by area; emission is
// one-sided (front face = counter-clockwise winding) and comes from the material graph, so
// textured and spectral emission work the same as in camera rays.

#include <cstdint>
#include <mutex>
#include <vector>

#include "materials/graph/compiled_material.h"
#include "materials/nodes/texture_provider.h"
#include "renderer/geometry/accel.h"
#include "renderer/geometry/mesh.h"
#include "renderer/lights/light.h"
#include "renderer/sampling/distribution_1d.h"

namespace ochre {

class AreaLight final : public Light {
 public:
  // `origin`: the rendering origin, for textured emission that reads world positions.
  AreaLight(const Mesh& mesh, const CompiledMaterial& material, const TextureProvider* textures,
            const Vec3& origin = {0, 0, 0});
  std::optional<LightSample> sample(const Vec3& ref, const Vec2& u,
                                    const SampledWavelengths& lambda) const override;
  float power() const override { return power_; }
  float importance(const Vec3& p) const override;
  // A material uniform over the surface has one emission spectrum (tabulated at 1 nm the first time it is
  // asked for: only light groups need it); a textured or position-dependent one has none (null).
  const Spectrum* emission_spectrum() const override;

  // Solid-angle pdf of sampling point p (normal ng) from ref, given the point is on this light.
  float pdf(const Vec3& ref, const Vec3& p, const Vec3& ng) const;
  // Emitted radiance at a point toward `to_viewer` (0 on the back side). A material uniform over the
  // surface (MaterialFacts::uniform_over_surface) is evaluated once per thread and set of wavelengths:
  // a path keeps its wavelengths, and every light sample and light hit along it reuses the value.
  SampledSpectrum emitted(const SurfacePoint& sp, const Vec3& to_viewer,
                          const SampledWavelengths& lambda) const;

 private:
  const Mesh& mesh_;
  const CompiledMaterial& material_;
  const TextureProvider* textures_;
  Vec3 origin_;
  uint64_t memo_key_;  // of the per-thread memo of a uniform emission (spectra/wavelength_memo.h)
  SampledSpectrum evaluate_emission(const SurfacePoint& sp, const SampledWavelengths& lambda) const;
  SampledSpectrum uniform_emission(const SampledWavelengths& lambda) const;
  SpectrumPtr uniform_emission_spectrum() const;
  mutable std::once_flag emission_once_;
  mutable SpectrumPtr emission_;  // emission_spectrum()

  Distribution1D triangles_;
  std::vector<Vec3>
      normals_;  // unit geometric normal of each triangle (0 if degenerate): one per sample saved
  float total_area_ = 0.0f;
  float power_ = 0.0f;
  Vec3 bound_center_;           // bounding sphere of the mesh
  float bound_radius2_ = 0.0f;  // its radius squared
  float mean_radiance_ = 0.0f;  // luminance, over the surface (importance())
};

}  // namespace ochre
