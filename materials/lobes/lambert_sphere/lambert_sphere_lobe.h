#pragma once
// LambertSphereLobe: the Lambertian-sphere BRDF (materials/lobes/lambert_sphere/lambert_sphere.h) as a Lobe,
// one particle albedo c per wavelength. Variants: full (exact single scattering + corrected fitted multiple
// scattering, d'Eon Eqs 17-45), fast (Eq 48, not energy conserving), exact (single scattering + the
// tabulated converged multiple scattering of materials/lobes/lambert_sphere/lambert_sphere_exact.h). An ideal
// depolarizer; cosine-weighted sampling (sample() and pdf() agree exactly). The c-dependent constants are
// built once per lobe for all the wavelengths together, and the evaluation's loop over the wavelengths runs
// as vector instructions (lambert_sphere_constant_lanes.h).

#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_constant_lanes.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "materials/lobes/lobe.h"

namespace ochre {

enum class LambertSphereVariant { kFull, kFast, kExact };

class LambertSphereLobe final : public Lobe {
 public:
  LambertSphereLobe(LambertSphereVariant variant, const SampledSpectrum& particle_albedo);

  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  // The bond albedo of Eq 47 per wavelength: within 1.4 % of the full model's bond albedo (0.014
  // absolute, at c = 1), a few % of its directional albedo.
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

  LambertSphereVariant variant() const { return variant_; }

 private:
  LambertSphereVariant variant_;
  LambertSphereConstantLanes fitted_;  // full and fast variants (one array per constant: the loops vectorize)
  LambertSphereExactConstants exact_[kSpectrumSamples];
  SampledSpectrum albedo_;
};

}  // namespace ochre
