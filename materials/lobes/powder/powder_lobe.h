#pragma once
// PowderLobe: the dry-powder BRDF (powder_model.h) as a Lobe, with parameters per hero wavelength, and
// its importance sampling (docs/materials/powder.md, "Sampling"): a one-sample mixture of
//   (a) cosine-weighted directions,
//   (b) a cone around the backscatter direction: in the projected disk, d = wi_xy - wo_xy is drawn from the
//       heavy-tailed density q(d) = w / (2 pi (w^2 + |d|^2)^(3/2)), w = (kappa / k0)(c0 + 1/mu_o), and
//       samples outside the unit disk are dropped (q stays untruncated),
//   (c) the Harvey-Shack lobe: wi_xy = -wo_xy + lambda F with F normal, variance 1 / (2 pi^2 l_c^2) per axis,
// chosen with probabilities from the lobe's energy estimates. Each wavelength has its own mixture (the
// cone's width scales with lambda, the surface lobe's too); sample() draws from the hero wavelength's and
// pdf() is the mean of the path's wavelengths' mixture pdfs, which weights the wavelengths by the balance
// heuristic (hero-wavelength spectral MIS, Wilkie et al. 2014) and is what MIS with light sampling sees.
// An ideal depolarizer.

#include <array>

#include "materials/lobes/lobe.h"
#include "materials/lobes/powder/powder_model.h"

namespace ochre {

// The mixture of one wavelength.
struct PowderSampling {
  float p_cone = 0.0f, p_surface = 0.0f;  // selection probabilities (cosine: the rest)
  float cone_width = 0.0f;                // w, in the projected disk
  float surface_sigma = 0.0f;             // standard deviation of wi_xy around -wo_xy
};

// kCosine samples cosine-weighted directions only (the baseline the mixture is measured against).
enum class PowderSamplingStrategy { kMixture, kCosine };

class PowderLobe final : public Lobe {
 public:
  // Per hero wavelength: the model's parameters and spectral values; wo is not known here, so the
  // sampling mixtures are built for each wo in sample() / pdf() (cheap: closed forms).
  PowderLobe(const std::array<PowderParams<float>, kSpectrumSamples>& params,
             const std::array<PowderWavelength<float>, kSpectrumSamples>& wavelengths,
             PowderSamplingStrategy strategy = PowderSamplingStrategy::kMixture);

  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse | kLobeGlossy; }
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const override;
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const override;
  SampledSpectrum albedo_hint(const Vec3& wo, const SampledWavelengths& lambda) const override;

  // The mixture of wavelength i for the viewer at wo (public for the tests and ochre-brdf).
  PowderSampling mixture(int i, const Vec3& wo) const;
  // Its solid-angle pdf of wi.
  float mixture_pdf(const PowderSampling& m, const Vec3& wo, const Vec3& wi) const;

 private:
  // The four mixtures for wo, built once per viewer direction: the integrator asks for the light sample's
  // value and pdf and then for a BSDF sample at the same vertex (a lobe lives at one vertex of one thread).
  const std::array<PowderSampling, kSpectrumSamples>& mixtures(const Vec3& wo) const;

  std::array<PowderParams<float>, kSpectrumSamples> params_;
  std::array<PowderWavelength<float>, kSpectrumSamples> wavelengths_;
  PowderSamplingStrategy strategy_;
  mutable std::array<PowderSampling, kSpectrumSamples> mixtures_{};
  mutable Vec3 mixtures_wo_{0.0f, 0.0f, -2.0f};  // no direction: nothing cached yet
};

}  // namespace ochre
