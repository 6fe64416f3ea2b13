#include "materials/lobes/closure.h"

#include <array>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace ochre {

void Closure::add_lobe(const Lobe* lobe, const SampledSpectrum& weight) {
  if (weight.is_black()) return;
  if (count_ == kMaxLobes) throw std::length_error("closure has more than 8 lobes");
  lobes_[count_++] = {lobe, weight};
  selection_valid_ = false;
}

void Closure::throw_lobe_out_of_range(int i) const {
  throw std::out_of_range("closure lobe " + std::to_string(i) + " of " + std::to_string(count_));
}

void Closure::scale(const SampledSpectrum& s) {
  for (int i = 0; i < count_; ++i) lobes_[i].weight *= s;
  emission_ *= s;
  selection_valid_ = false;
}

void Closure::append(const Closure& other) {
  for (int i = 0; i < other.count_; ++i) add_lobe(other.lobes_[i].lobe, other.lobes_[i].weight);
  emission_ += other.emission_;
  if (!has_tangent_ && other.has_tangent_) set_tangent(other.tangent_);
}

bool Closure::has_non_delta_lobes() const {
  for (int i = 0; i < count_; ++i)
    if (!lobes_[i].lobe->is_delta()) return true;
  return false;
}

bool Closure::has_delta_lobes() const {
  for (int i = 0; i < count_; ++i)
    if (lobes_[i].lobe->is_delta()) return true;
  return false;
}

bool Closure::has_transmission() const {
  for (int i = 0; i < count_; ++i)
    if (lobes_[i].lobe->flags() & kLobeTransmission) return true;
  return false;
}

bool Closure::polarizes() const {
  for (int i = 0; i < count_; ++i)
    if (lobes_[i].lobe->polarizes()) return true;
  return false;
}

SampledSpectrum Closure::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const {
  return eval_after_sample(wo, wi, lambda, -1, nullptr);
}

SampledSpectrum Closure::eval_after_sample(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda,
                                           int sampled_lobe, const LobeSample* sample) const {
  SampledSpectrum f;
  for (int i = 0; i < count_; ++i) {
    const WeightedLobe& l = lobes_[i];
    if (l.lobe->is_delta()) continue;
    if (i == sampled_lobe && sample->has_value)
      f += l.weight * sample->value;  // the lobe's own eval() in wi, from its sample
    else
      f += l.weight * l.lobe->eval(wo, wi, lambda);
  }
  return f;
}

bool Closure::has_polarizing_non_delta_lobes() const {
  for (int i = 0; i < count_; ++i)
    if (!lobes_[i].lobe->is_delta() && lobes_[i].lobe->polarizes()) return true;
  return false;
}

MuellerResponse Closure::eval_mueller(const Vec3& wo, const Vec3& wi,
                                      const SampledWavelengths& lambda) const {
  if (!has_polarizing_non_delta_lobes()) return depolarizing_response(eval(wo, wi, lambda), wo, wi);
  MuellerResponse sum;
  bool have_frames = false;
  SampledSpectrum depolarized(0.0f);  // depolarizers only add to M00, in any frame
  for (int i = 0; i < count_; ++i) {
    const WeightedLobe& l = lobes_[i];
    if (l.lobe->is_delta()) continue;
    if (!l.lobe->polarizes()) {
      depolarized += l.weight * l.lobe->eval(wo, wi, lambda);
      continue;
    }
    MuellerResponse r = l.lobe->eval_mueller(wo, wi, lambda);
    if (!have_frames) {
      sum.in_x = r.in_x;
      sum.out_x = r.out_x;
      sum.m = r.m * l.weight;
      have_frames = true;
      continue;
    }
    // Bring this lobe's frames to the common ones: M' = R(out_r -> out) M R(in -> in_r).
    const Mueller out_rotation = stokes_basis_rotation(wo, r.out_x, sum.out_x);
    const Mueller in_rotation = stokes_basis_rotation(-wi, sum.in_x, r.in_x);
    for (int k = 0; k < kSpectrumSamples; ++k) {
      const Mueller term = out_rotation * r.m[k] * in_rotation;
      for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) sum.m[k](row, col) += term(row, col) * l.weight[k];
    }
  }
  for (int k = 0; k < kSpectrumSamples; ++k) sum.m[k](0, 0) += depolarized[k];
  return sum;
}

float Closure::selection_weights(const Vec3& wo, const SampledWavelengths& lambda,
                                 std::array<float, kMaxLobes>& p) const {
  const bool terminated = lambda.secondary_terminated();
  // The same wo bit for bit (not ==, for which -0 equals +0): the cached weights are then exactly those
  // the lobes would give again.
  const bool same_wo =
      std::bit_cast<std::array<uint32_t, 3>>(wo) == std::bit_cast<std::array<uint32_t, 3>>(selection_wo_);
  if (!(selection_valid_ && same_wo && terminated == selection_terminated_)) {
    float total = 0.0f;
    for (int i = 0; i < count_; ++i) {
      const WeightedLobe& l = lobes_[i];
      // Weighted albedo averaged over the wavelengths (Cycles' sample_weight, with the lobe's albedo).
      selection_[i] = std::max(0.0f, (l.weight * l.lobe->albedo_hint(wo, lambda)).average());
      total += selection_[i];
    }
    selection_total_ = total;
    selection_wo_ = wo;
    selection_terminated_ = terminated;
    selection_valid_ = true;
  }
  for (int i = 0; i < count_; ++i) p[i] = selection_[i];
  return selection_total_;
}

float Closure::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const {
  // One lobe: its selection probability is 1 (or nothing can be sampled), so no albedo estimates.
  if (count_ == 1) return lobes_[0].lobe->is_delta() ? 0.0f : lobes_[0].lobe->pdf(wo, wi, lambda);
  return pdf_after_sample(wo, wi, lambda, -1, nullptr);
}

float Closure::pdf_after_sample(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda,
                                int sampled_lobe, const LobeSample* sample) const {
  std::array<float, kMaxLobes> p{};
  const float total = selection_weights(wo, lambda, p);
  if (total <= 0.0f) return 0.0f;
  float pdf = 0.0f;
  for (int i = 0; i < count_; ++i) {
    if (lobes_[i].lobe->is_delta() || !(p[i] > 0.0f)) continue;
    const bool own = i == sampled_lobe && sample->has_value;  // the lobe's own pdf() in wi, from its sample
    pdf += p[i] / total * (own ? sample->pdf : lobes_[i].lobe->pdf(wo, wi, lambda));
  }
  return pdf;
}

std::optional<LobeSample> Closure::sample(const Vec3& wo, float u_choice, const Vec2& u,
                                          const SampledWavelengths& lambda) const {
  if (count_ == 1) return sample_only_lobe(wo, u_choice, u, lambda);
  std::array<float, kMaxLobes> p{};
  const float total = selection_weights(wo, lambda, p);
  if (total <= 0.0f) return std::nullopt;

  // Pick lobe k with probability p_k / total; rescale u_choice to [0,1) for the lobe's own use.
  int k = 0;
  float cdf = 0.0f;
  const float target = u_choice * total;
  for (; k < count_ - 1; ++k) {
    if (target < cdf + p[k]) break;
    cdf += p[k];
  }
  while (p[k] <= 0.0f && k > 0) --k;  // guard against rounding past the last non-zero entry
  const float pick = p[k] / total;
  const float u_rest = std::min((target - cdf) / p[k], 0.99999994f);

  const WeightedLobe& chosen = lobes_[k];
  std::optional<LobeSample> s = chosen.lobe->sample(wo, std::max(u_rest, 0.0f), u, lambda);
  if (!s) return std::nullopt;

  if (s->delta) {
    s->weight = s->weight * chosen.weight / pick;
    s->pdf *= pick;
    if (s->has_mueller) s->mueller.m = s->mueller.m * (chosen.weight / pick);
    return s;
  }
  // One BSDF for MIS: value and pdf of the whole non-delta mixture in the sampled direction.
  const float pdf = pdf_after_sample(wo, s->wi, lambda, k, &*s);
  if (!(pdf > 0.0f)) return std::nullopt;
  s->pdf = pdf;
  s->weight = eval_after_sample(wo, s->wi, lambda, k, &*s) * (abs_cos_theta(s->wi) / pdf);
  s->has_mueller = false;  // the mixture's Mueller response comes from eval_mueller() when needed
  return s;
}

// The common case of one lobe: no choice to make, and the mixture is the lobe itself, so its own sample
// (direction, pdf, f |cos| / pdf) is the closure's, times the lobe weight. Same estimator as the general
// path, without a second evaluation of the lobe's pdf and value in the sampled direction.
std::optional<LobeSample> Closure::sample_only_lobe(const Vec3& wo, float u_choice, const Vec2& u,
                                                    const SampledWavelengths& lambda) const {
  const WeightedLobe& only = lobes_[0];
  // Every return returns `s` (no copy of the sample's 0.5 KB Mueller response).
  std::optional<LobeSample> s = only.lobe->sample(wo, u_choice, u, lambda);
  if (s && !(s->pdf > 0.0f)) s.reset();
  if (!s) return s;
  s->weight = s->weight * only.weight;
  if (!s->delta)
    s->has_mueller = false;  // as in the mixture: eval_mueller() gives the response when it is needed
  else if (s->has_mueller)
    s->mueller.m = s->mueller.m * only.weight;
  return s;
}

}  // namespace ochre
