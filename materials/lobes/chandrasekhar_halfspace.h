#pragma once
// Chandrasekhar's BRDF of a half space of isotropic scatterers with single-scattering albedo c
// (Chandrasekhar 1960; d'Eon Eq 21; the "mirror-sphere" volumetric BRDF of the paper's comparisons):
//   f = c / (4 pi) H(mu_i) H(mu_o) / (mu_i + mu_o),
// with the exact isotropic H function (materials/numerics/h_function.h) tabulated once on first use over
// x = sqrt(mu) and s = sqrt(1 - c) (65 x 33 nodes, bilinear; the error is measured in
// tests/materials/lobes/lambert_sphere/lobes_test.cpp). Energy conserving at c = 1. An ideal depolarizer;
// cosine-weighted sampling.

#include "materials/lobes/lobe.h"

namespace ochre {

// Interpolation constants of one albedo.
struct ChandrasekharConstants {
  float c = 0.0f;
  int s_index = 0;
  float s_weight = 0.0f;
};
ChandrasekharConstants chandrasekhar_constants(float c);
// H(mu; c) from the table (mu clamped to [0, 1]).
float chandrasekhar_h(const ChandrasekharConstants& k, float mu);
// The BRDF; 0 when mu_i <= 0 or mu_o <= 0.
float chandrasekhar_brdf(const ChandrasekharConstants& k, float mu_i, float mu_o);
// Bytes of the table.
size_t chandrasekhar_table_bytes();

class ChandrasekharLobe final : public Lobe {
 public:
  explicit ChandrasekharLobe(const SampledSpectrum& albedo);

  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  // Directional albedo 1 - H(mu_o) sqrt(1 - c) (Chandrasekhar's identity for isotropic scattering).
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

 private:
  ChandrasekharConstants k_[kSpectrumSamples];
};

}  // namespace ochre
