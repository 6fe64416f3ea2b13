#pragma once
// Conductor lobes: Fresnel reflection off a metal with a complex index eta = n - i k per wavelength
// (materials/lobes/fresnel.h), polarizing (kLobePolarizing). Both reflect only light arriving from above
// the surface (wo.z > 0, like every opaque lobe here).
// - SmoothConductorLobe: a perfect mirror (delta): one exit wi = (-wo.x, -wo.y, wo.z) with probability
//   1, weight F(cos) per wavelength, Mueller matrix = the Fresnel reflection matrix.
// - RoughConductorLobe: GGX microfacets (materials/lobes/microfacet_reflection.h), value
//   F(wo.h) D G2 / (4 cos_o cos_i); polarized by the Fresnel Mueller matrix at the microfacet normal h.
// Mueller frames (lobe.h MuellerResponse): in_x = out_x = the s axis cross(wi, m) of the reflecting
// (micro)normal m, y = cross(d, x) per beam: the frames of the note's matrices, no further sign flips
// (derivation in docs/polarization.md; checked by tests/materials/lobes/conductor_test.cpp).
// Single scattering only: a rough conductor loses the energy of multiply scattered light (measured in
// conductor_test: RoughConductorFurnace).

#include "materials/lobes/lobe.h"
#include "materials/lobes/microfacet_reflection.h"

namespace ochre {

class SmoothConductorLobe final : public Lobe {
 public:
  SmoothConductorLobe(const SampledSpectrum& n, const SampledSpectrum& k) : n_(n), k_(k) {}

  uint32_t flags() const override { return kLobeReflection | kLobeDelta | kLobePolarizing | kLobeMirror; }
  SampledSpectrum eval(const Vec3&, const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(0.0f);
  }
  float pdf(const Vec3&, const Vec3&, const SampledWavelengths&) const override { return 0.0f; }
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi,
                               const SampledWavelengths& lambda) const override;
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

 private:
  SampledSpectrum n_, k_;
};

class RoughConductorLobe final : public Lobe {
 public:
  RoughConductorLobe(const SampledSpectrum& n, const SampledSpectrum& k, float alpha_x, float alpha_y)
      : n_(n), k_(k), microfacets_(GgxDistribution(alpha_x, alpha_y)) {}
  RoughConductorLobe(const SampledSpectrum& n, const SampledSpectrum& k, float alpha)
      : RoughConductorLobe(n, k, alpha, alpha) {}

  uint32_t flags() const override { return kLobeReflection | kLobeGlossy | kLobePolarizing; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi,
                               const SampledWavelengths& lambda) const override;
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

 private:
  SampledSpectrum n_, k_;
  MicrofacetReflection microfacets_;
};

// The Fresnel reflection Mueller matrix of a conductor at each wavelength (eta = n - i k).
MuellerSpectrum conductor_reflection_mueller(float cos_i, const SampledSpectrum& n, const SampledSpectrum& k);

}  // namespace ochre
