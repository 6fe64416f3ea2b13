#pragma once
// VGrooveLobe: a surface of parallel V-grooves with specular facets (materials/lobes/vgroove/vgroove.h)
// as a delta BSDF lobe. sample() draws the entry position uniformly across the cavity's opening, finds
// the ray's exact path, and returns its exit direction with the reflectance of that path and, for the
// polarizing models, its Mueller matrix (Saint-Pierre et al. 2019, Sec 3). The estimate is unbiased for
// R(theta, phi) of Eq 36: the mean over entry positions. eval() and pdf() are 0 (a sum of Dirac deltas).
//
// The groove axis is a unit vector of the local tangent plane (z = 0); the groove frame is x = axis,
// y = cross(z, axis), z = the normal.

#include "materials/lobes/lobe.h"
#include "materials/lobes/reflection_chain.h"
#include "materials/lobes/vgroove/vgroove.h"

namespace ochre {

// Facet material per hero wavelength: complex index n - i k, or an ideal mirror.
struct FacetSpectrum {
  SampledSpectrum n{1.5f}, k{0.0f};
  bool mirror = false;

  FacetIndex at(int wavelength) const {
    return mirror ? FacetIndex::ideal_mirror() : FacetIndex::conductor(n[wavelength], k[wavelength]);
  }
};

class VGrooveLobe final : public Lobe {
 public:
  // alpha in radians (0, pi]; reflection_limit: paths with more reflections are absorbed (0 = none).
  VGrooveLobe(double alpha, const Vec3& axis, const FacetSpectrum& facet, ChainModel model, int reflection_limit);

  uint32_t flags() const override;
  SampledSpectrum eval(const Vec3&, const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(0.0f);
  }
  float pdf(const Vec3&, const Vec3&, const SampledWavelengths&) const override { return 0.0f; }
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const override;
  // The flat surface's Fresnel reflectance at wo (a cheap hint for choosing among lobes).
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

 private:
  Vec3d to_groove(const Vec3& v) const;
  Vec3 from_groove(const Vec3d& v) const;

  VGroove groove_;
  Vec3d axis_, across_;  // groove frame x and y in local coordinates
  FacetSpectrum facet_;
  ChainModel model_;
  int reflection_limit_;
};

}  // namespace ochre
