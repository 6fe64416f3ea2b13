#pragma once
// VGrooveLobe: a surface of parallel V-grooves with specular facets (materials/lobes/vgroove/vgroove.h)
// as a delta BSDF lobe. sample() draws the entry position uniformly across the cavity's opening, finds
// the ray's exact path, and returns its exit direction with the reflectance of that path and, for the
// polarizing models, its Mueller matrix (Saint-Pierre et al. 2019, Sec 3). The estimate is unbiased for
// R(theta, phi) of Eq 36: the mean over entry positions. eval() and pdf() are 0 (a sum of Dirac deltas).
// The groove axis is a unit vector of the local tangent plane (groove_frame.h).

#include "materials/lobes/lobe.h"
#include "materials/lobes/vgroove/groove_frame.h"
#include "materials/lobes/vgroove/vgroove.h"

namespace ochre {

class VGrooveLobe final : public Lobe {
 public:
  // alpha in radians (0, pi]; reflection_limit: paths with more reflections are absorbed (0 = none).
  VGrooveLobe(double alpha, const Vec3& axis, const FacetSpectrum& facet, ChainModel model,
              int reflection_limit);

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
  VGroove groove_;
  GrooveFrame frame_;
  FacetSpectrum facet_;
  ChainModel model_;
  int reflection_limit_;
};

// Shared by the groove lobes: the flat facet's Fresnel reflectance at wo.
SampledSpectrum facet_albedo_hint(const FacetSpectrum& facet, const Vec3& wo);

}  // namespace ochre
