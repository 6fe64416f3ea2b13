#pragma once
// MicrogrooveLobe: a surface of parallel grooves described by explicit microgeometry, a periodic profile
// (groove_profile.h), as a delta BSDF lobe. sample() enters the profile's opening at a uniformly drawn
// position, traces the ray through the actual facets with a Fresnel reflection at each (the same chain
// models as VGrooveLobe: reflection_chain.h), and returns the exit direction with the path's
// reflectance and Mueller matrix. For a symmetric V profile it reproduces VGrooveLobe ray for ray; for
// the other profiles it is the only model. A mix of V grooves (equal widths, dihedral angles uniform in
// [alpha_min, alpha_max]) picks each sample's groove with u_choice.

#include "materials/lobes/lobe.h"
#include "materials/lobes/vgroove/groove_frame.h"
#include "materials/lobes/vgroove/groove_profile.h"

namespace ochre {

// The grooves: one profile (owned by the material, outlives the lobe), or a mix of V angles.
struct MicrogrooveShape {
  const GrooveProfile* profile = nullptr;   // null: the V mix below
  double alpha_min = 0.0, alpha_max = 0.0;  // radians
};

class MicrogrooveLobe final : public Lobe {
 public:
  // The longest path traced; longer ones are absorbed (a V of 0.18 degrees would need 1000 reflections).
  static constexpr int kMaxReflections = 1000;

  MicrogrooveLobe(const MicrogrooveShape& shape, const Vec3& axis, const FacetSpectrum& facet,
                  ChainModel model, int reflection_limit);

  uint32_t flags() const override;
  SampledSpectrum eval(const Vec3&, const Vec3&, const SampledWavelengths&) const override {
    return SampledSpectrum(0.0f);
  }
  float pdf(const Vec3&, const Vec3&, const SampledWavelengths&) const override { return 0.0f; }
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const override;
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

 private:
  std::optional<LobeSample> sample_profile(const GrooveProfile& profile, const Vec3d& e, double u) const;

  MicrogrooveShape shape_;
  GrooveFrame frame_;
  FacetSpectrum facet_;
  ChainModel model_;
  int reflection_limit_;
};

}  // namespace ochre
