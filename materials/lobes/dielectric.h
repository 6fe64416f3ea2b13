#pragma once
// Dielectric lobes with a real, wavelength-independent relative index eta = n_inside / n_outside
// (the surface normal, local +z, points outside). Polarizing (kLobePolarizing), Mueller frames as for
// the conductor: in_x = out_x = the s axis of the (micro)normal, y = cross(d, x) per beam.
// - SmoothDielectricLobe: a delta lobe with two exits, reflection and refraction, picked with u_choice
//   in proportion to the Fresnel R and T = 1 - R (total internal reflection: reflection only). wo may
//   lie on either side: below the surface (inside) the index is inverted. The refracted exit's weight
//   carries the radiance compression (n_wo / n_wi)^2 of pbrt-v4 (radiance transport from the camera):
//   weight = T (n_wo / n_wi)^2 / T. With `opaque` set (e.g. black glass, eta = 1.5) the refracted part
//   is absorbed: the only exit is the reflection (probability 1, weight R) and nothing is returned for
//   wo below the surface (an opaque body has no inside).
// - RoughDielectricLobe: GGX microfacet REFLECTION only (materials/lobes/microfacet_reflection.h), value
//   F_dielectric(wo.h) D G2 / (4 cos_o cos_i), polarized by the Fresnel Mueller matrix at h. The
//   refracted part is not traced (it is lost: the lobe suits opaque or black glass-like coatings, not
//   rough glass); only light from above the surface (wo.z > 0) is reflected.

#include "materials/lobes/lobe.h"
#include "materials/lobes/microfacet_reflection.h"

namespace ochre {

class SmoothDielectricLobe final : public Lobe {
 public:
  SmoothDielectricLobe(float eta, bool opaque) : eta_(eta), opaque_(opaque) {}

  uint32_t flags() const override {
    return kLobeReflection | (opaque_ ? kLobeMirror : kLobeTransmission) | kLobeDelta | kLobePolarizing;
  }
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
  LobeSample reflection(const Vec3& wo, float probability) const;
  std::optional<LobeSample> refraction(const Vec3& wo, float probability) const;

  float eta_;
  bool opaque_;
};

class RoughDielectricLobe final : public Lobe {
 public:
  RoughDielectricLobe(float eta, float alpha_x, float alpha_y)
      : eta_(eta), microfacets_(GgxDistribution(alpha_x, alpha_y)) {}
  RoughDielectricLobe(float eta, float alpha) : RoughDielectricLobe(eta, alpha, alpha) {}

  uint32_t flags() const override { return kLobeReflection | kLobeGlossy | kLobePolarizing; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi,
                               const SampledWavelengths& lambda) const override;
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

 private:
  float eta_;
  MicrofacetReflection microfacets_;
};

// Refraction of wo through the interface with normal +z and relative index eta (n_inside /
// n_outside), from either side; nothing under total internal reflection. pbrt-v4's Refract().
std::optional<Vec3> refract_through_z(const Vec3& wo, float eta);

}  // namespace ochre
