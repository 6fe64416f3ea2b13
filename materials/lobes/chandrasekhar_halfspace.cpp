#include "materials/lobes/chandrasekhar_halfspace.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "materials/lobes/cosine_lobe_sampling.h"
#include "materials/numerics/h_function.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace {

// Uniform nodes over x = sqrt(mu) and s = sqrt(1 - c) in [0, 1] (first use: ~0.1 s).
constexpr int kHXNodes = 65;
constexpr int kHSNodes = 33;

struct HTable {
  std::vector<float> h;  // [s * kHXNodes + x]
  HTable() : h(kHXNodes * kHSNodes) {
    for (int s = 0; s < kHSNodes; ++s) {
      const double sv = double(s) / (kHSNodes - 1), c = 1.0 - sv * sv;
      for (int x = 0; x < kHXNodes; ++x) {
        const double xv = double(x) / (kHXNodes - 1);
        h[s * kHXNodes + x] = float(isotropic_h_exact(xv * xv, c));
      }
    }
  }
};

const HTable& h_table() {
  static const HTable t;
  return t;
}

}  // namespace

ChandrasekharConstants chandrasekhar_constants(float c) {
  ChandrasekharConstants k;
  k.c = nan_safe_clamp(c, 0.0f, 1.0f);  // NaN -> 0: c gives the index
  const float f = std::sqrt(1.0f - k.c) * float(kHSNodes - 1);
  k.s_index = std::min(int(f), kHSNodes - 2);
  k.s_weight = std::clamp(f - float(k.s_index), 0.0f, 1.0f);
  return k;
}

float chandrasekhar_h(const ChandrasekharConstants& k, float mu) {
  const std::vector<float>& h = h_table().h;
  const float f = std::sqrt(nan_safe_clamp(mu, 0.0f, 1.0f)) * float(kHXNodes - 1);
  const int x = std::min(int(f), kHXNodes - 2);
  const float t = f - float(x);
  const float* lo = &h[k.s_index * kHXNodes + x];
  const float* hi = lo + kHXNodes;
  return (1.0f - k.s_weight) * ((1.0f - t) * lo[0] + t * lo[1]) +
         k.s_weight * ((1.0f - t) * hi[0] + t * hi[1]);
}

float chandrasekhar_brdf(const ChandrasekharConstants& k, float mu_i, float mu_o) {
  if (!(mu_i > 0.0f) || !(mu_o > 0.0f)) return 0.0f;
  return k.c * 0.25f * kInvPi * chandrasekhar_h(k, mu_i) * chandrasekhar_h(k, mu_o) / (mu_i + mu_o);
}

size_t chandrasekhar_table_bytes() {
  return h_table().h.size() * sizeof(float);
}

ChandrasekharLobe::ChandrasekharLobe(const SampledSpectrum& albedo) {
  for (int i = 0; i < kSpectrumSamples; ++i) k_[i] = chandrasekhar_constants(albedo[i]);
}

SampledSpectrum ChandrasekharLobe::eval(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  SampledSpectrum f;
  for (int i = 0; i < kSpectrumSamples; ++i) f[i] = chandrasekhar_brdf(k_[i], wi.z, wo.z);
  return f;
}

float ChandrasekharLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths&) const {
  return cosine_lobe_pdf(wo, wi);
}

std::optional<LobeSample> ChandrasekharLobe::sample(const Vec3& wo, float, const Vec2& u,
                                                    const SampledWavelengths& lambda) const {
  std::optional<LobeSample> s = sample_cosine_lobe(wo, u);
  if (s) s->weight = eval(wo, s->wi, lambda) * (s->wi.z / s->pdf);
  return s;
}

SampledSpectrum ChandrasekharLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  SampledSpectrum a;
  const float mu = std::max(0.0f, wo.z);
  for (int i = 0; i < kSpectrumSamples; ++i)
    a[i] = std::clamp(1.0f - chandrasekhar_h(k_[i], mu) * std::sqrt(1.0f - k_[i].c), 0.0f, 1.0f);
  return a;
}

}  // namespace ochre
