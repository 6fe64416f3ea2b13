#pragma once
// Closure: what a material graph evaluates to at a shading point, with OSL semantics: a
// weighted sum of primitive lobes (weight = a spectrum per lobe) plus emitted radiance.
// The renderer samples and evaluates the sum as one BSDF.

#include <array>
#include <optional>

#include "materials/lobes/lobe.h"

namespace ochre {

struct WeightedLobe {
  const Lobe* lobe = nullptr;
  SampledSpectrum weight;
};

class Closure {
 public:
  static constexpr int kMaxLobes = 8;

  Closure() = default;
  // Copies carry only the lobes in use: a closure is copied at every path vertex (from the per-thread
  // memo), and the unused slots of the fixed array (320 bytes with eight wavelengths) are never read.
  Closure(const Closure& other) { *this = other; }
  Closure& operator=(const Closure& other) {
    for (int i = 0; i < other.count_; ++i) lobes_[i] = other.lobes_[i];
    count_ = other.count_;
    emission_ = other.emission_;
    tangent_ = other.tangent_;
    has_tangent_ = other.has_tangent_;
    selection_valid_ = false;
    return *this;
  }
  // Back to no lobes, no emission and no tangent (the unused lobe slots are left as they are).
  void clear() {
    count_ = 0;
    selection_valid_ = false;
    emission_ = SampledSpectrum(0.0f);
    tangent_ = Vec3{};
    has_tangent_ = false;
  }

  // Adds a lobe with its weight; lobes with zero weight are dropped, equal lobes are not merged.
  void add_lobe(const Lobe* lobe, const SampledSpectrum& weight);
  void add_emission(const SampledSpectrum& radiance) { emission_ += radiance; }
  void set_emission(const SampledSpectrum& radiance) { emission_ = radiance; }
  // Multiplies every lobe weight and the emission (closure scale).
  void scale(const SampledSpectrum& s);
  // this = this + other (closure add).
  void append(const Closure& other);

  // Anisotropic lobes (V-grooves) are defined relative to a tangent direction: the first such closure
  // sets it (world space) and its lobe's axis is local x; the renderer takes the x axis of the shading
  // frame from it (the tangent projected onto the tangent plane). Later anisotropic closures express
  // their own axis relative to this one.
  void set_tangent(const Vec3& world_tangent) {
    tangent_ = world_tangent;
    has_tangent_ = true;
  }
  bool has_tangent() const { return has_tangent_; }
  const Vec3& tangent() const { return tangent_; }

  int lobe_count() const { return count_; }
  // Lobe i of the lobe_count() lobes; throws std::out_of_range for any other i (the unused slots hold
  // stale lobes after clear() or a copy of fewer lobes).
  const WeightedLobe& lobe(int i) const {
    if (i < 0 || i >= count_) throw_lobe_out_of_range(i);
    return lobes_[static_cast<std::size_t>(i)];
  }
  const SampledSpectrum& emission() const { return emission_; }
  bool has_lobes() const { return count_ > 0; }
  bool has_non_delta_lobes() const;
  bool has_delta_lobes() const;
  bool polarizes() const;
  bool has_transmission() const;  // some lobe can refract (the surface's two sides differ)

  // Sum of the non-delta lobes' weighted values (no cosine).
  SampledSpectrum eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const;
  // Mueller response of the non-delta lobes (no cosine): their matrices brought to common frames (those
  // of the first polarizing lobe) and summed; an ideal depolarizer when no non-delta lobe polarizes.
  // Its M00 equals eval().
  MuellerResponse eval_mueller(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const;
  bool has_polarizing_non_delta_lobes() const;
  // Pdf of sample() producing wi through its non-delta lobes (the one-sample mixture pdf).
  float pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const;
  // Picks a lobe with probability proportional to its weighted albedo, samples it; for a
  // non-delta pick, the returned weight and pdf are those of the whole non-delta mixture
  // (so MIS sees one BSDF). u_choice is reused after the pick (rescaled).
  std::optional<LobeSample> sample(const Vec3& wo, float u_choice, const Vec2& u,
                                   const SampledWavelengths& lambda) const;

 private:
  [[noreturn]] void throw_lobe_out_of_range(int i) const;
  std::optional<LobeSample> sample_only_lobe(const Vec3& wo, float u_choice, const Vec2& u,
                                             const SampledWavelengths& lambda) const;
  // eval() in the direction lobe `sampled_lobe` sampled (`sample`), reusing the value the lobe computed
  // for its sample's weight where it kept it (has_value): the same bits as eval(), one evaluation fewer.
  // sampled_lobe = -1: none (eval() itself).
  SampledSpectrum eval_after_sample(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda,
                                    int sampled_lobe, const LobeSample* sample) const;
  // pdf() of a closure of several lobes, likewise reusing the sampled lobe's own pdf (has_value).
  float pdf_after_sample(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda, int sampled_lobe,
                         const LobeSample* sample) const;
  // Lobe selection probabilities; returns their sum (0 when nothing can be sampled).
  float selection_weights(const Vec3& wo, const SampledWavelengths& lambda,
                          std::array<float, kMaxLobes>& p) const;

  std::array<WeightedLobe, kMaxLobes> lobes_{};
  int count_ = 0;
  // The selection weights of the last wo: a path vertex asks for them two or three times (the light
  // sample's pdf, the BSDF sample and its pdf), and a lobe's albedo_hint can cost several BRDF evaluations
  // per wavelength (the powder's). Forgotten whenever the lobes or their weights change.
  mutable std::array<float, kMaxLobes> selection_{};
  mutable float selection_total_ = 0.0f;
  mutable Vec3 selection_wo_;
  mutable bool selection_terminated_ = false;  // the wavelengths' state they were computed for
  mutable bool selection_valid_ = false;
  SampledSpectrum emission_;
  Vec3 tangent_;
  bool has_tangent_ = false;
};

}  // namespace ochre
