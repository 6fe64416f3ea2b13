#pragma once
// ClosureLobe: a whole Closure seen through the Lobe interface (its eval, mixture pdf and one-sample
// sampler), so that checks written for one lobe, such as the chi-square test of
// materials/lobes/sampling_check.h, run on any material.

#include "materials/lobes/closure.h"
#include "materials/lobes/lobe.h"

namespace ochre {

class ClosureLobe final : public Lobe {
 public:
  explicit ClosureLobe(const Closure& closure) : closure_(closure) {}

  uint32_t flags() const override {
    uint32_t f = 0;
    for (int i = 0; i < closure_.lobe_count(); ++i) f |= closure_.lobe(i).lobe->flags();
    return f;
  }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override {
    return closure_.eval(wo, wi, lambda);
  }
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override {
    return closure_.pdf(wo, wi, lambda);
  }
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override {
    return closure_.sample(wo, u_choice, u, lambda);
  }
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override {
    SampledSpectrum sum(0.0f);
    for (int i = 0; i < closure_.lobe_count(); ++i)
      sum += closure_.lobe(i).weight * closure_.lobe(i).lobe->albedo_hint(wo, lambda);
    return sum;
  }

 private:
  const Closure& closure_;
};

}  // namespace ochre
