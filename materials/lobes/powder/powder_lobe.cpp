#include "materials/lobes/powder/powder_lobe.h"

#include <algorithm>
#include <cmath>

#include "materials/core/sampling.h"

namespace ochre {

PowderLobe::PowderLobe(const std::array<PowderParams<float>, kSpectrumSamples>& params,
                       const std::array<PowderWavelength<float>, kSpectrumSamples>& wavelengths,
                       PowderSamplingStrategy strategy)
    : params_(params), wavelengths_(wavelengths), strategy_(strategy) {}

// noinline: GCC 12 at -O3 miscompiles this loop once inlined into sample() (every weight 0; correct with
// -fno-tree-pre, at -O2, with clang 14, or out of line); tests/materials/lobes/powder checks every sampled
// weight.
__attribute__((noinline)) SampledSpectrum PowderLobe::eval(const Vec3& wo, const Vec3& wi,
                                                           const SampledWavelengths&) const {
  SampledSpectrum f;
  for (int i = 0; i < kSpectrumSamples; ++i) f[i] = powder_brdf(params_[i], wavelengths_[i], wi, wo);
  return f;
}

PowderSampling PowderLobe::mixture(int i, const Vec3& wo) const {
  const PowderParams<float>& p = params_[i];
  const PowderWavelength<float>& w = wavelengths_[i];
  PowderSampling m;
  if (strategy_ == PowderSamplingStrategy::kCosine) return m;
  const float mu_o = std::max(wo.z, 1e-4f);
  const float c0 = std::sqrt(std::max(0.0f, 3.0f * (1.0f - w.rho) * (1.0f - w.rho * p.g)));
  // The cone's half-width in the projected disk: where alpha = c0 + 1/mu_o halves the cyclical term.
  m.cone_width = p.kappa * w.lambda_um / (2.0f * kPi) * (c0 + 1.0f / mu_o);
  m.surface_sigma = w.lambda_um / (kPi * p.correlation_length * std::sqrt(2.0f));
  // Energy estimates from one evaluation at exact backscatter: the volume's from its smooth part
  // pi (L1 + L2), the peak's share from the excess C / (L1 + L2 + C) there, the surface's from its total
  // integrated scatter (4 pi mu / lambda)^2 (Harvey-Shack; docs/materials/powder.md).
  const PowderTerms<float> back = powder_terms(p, w, wo, wo);
  const float volume = std::max(0.0f, p.volume_amplitude) * kPi * (back.l1 + back.l2);
  const float tis = 4.0f * kPi * mu_o / w.lambda_um;
  const float surface =
      p.surface == PowderSurface::kHarveyShack ? std::max(0.0f, p.surface_amplitude) * tis * tis : 0.0f;
  const float total = volume + surface;
  if (!(total > 0.0f)) return m;
  const float peak = back.volume() > 0.0f ? back.c / back.volume() : 0.0f;
  m.p_surface = std::clamp(surface / total, 0.0f, 0.9f);
  m.p_cone = (1.0f - m.p_surface) * std::clamp(0.5f * peak, 0.0f, 0.5f) * (volume / total);
  return m;
}

float PowderLobe::mixture_pdf(const PowderSampling& m, const Vec3& wo, const Vec3& wi) const {
  if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
  float pdf = (1.0f - m.p_cone - m.p_surface) * wi.z * kInvPi;
  if (m.p_cone > 0.0f) {
    const float dx = wi.x - wo.x, dy = wi.y - wo.y, w = m.cone_width;
    const float s = w * w + dx * dx + dy * dy;
    pdf += m.p_cone * wi.z * w / (2.0f * kPi * s * std::sqrt(s));
  }
  if (m.p_surface > 0.0f) {
    const float sx = wi.x + wo.x, sy = wi.y + wo.y, v = m.surface_sigma * m.surface_sigma;
    pdf += m.p_surface * wi.z * std::exp(-(sx * sx + sy * sy) / (2.0f * v)) / (2.0f * kPi * v);
  }
  return pdf;
}

const std::array<PowderSampling, kSpectrumSamples>& PowderLobe::mixtures(const Vec3& wo) const {
  if (!(wo == mixtures_wo_)) {
    for (int i = 0; i < kSpectrumSamples; ++i) mixtures_[i] = mixture(i, wo);
    mixtures_wo_ = wo;
  }
  return mixtures_;
}

float PowderLobe::pdf(const Vec3& wo, const Vec3& wi, const SampledWavelengths& lambda) const {
  if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
  const std::array<PowderSampling, kSpectrumSamples>& m = mixtures(wo);
  // After a dispersive event only the hero wavelength carries light: no averaging over the others.
  if (lambda.secondary_terminated()) return mixture_pdf(m[0], wo, wi);
  float sum = 0.0f;
  for (int i = 0; i < kSpectrumSamples; ++i) sum += mixture_pdf(m[i], wo, wi);
  return sum / kSpectrumSamples;
}

namespace {

// A point of the projected disk lifted to the hemisphere; nothing outside the disk.
std::optional<Vec3> lift(float x, float y) {
  const float r2 = x * x + y * y;
  if (!(r2 < 1.0f)) return std::nullopt;
  return Vec3(x, y, std::sqrt(1.0f - r2));
}

}  // namespace

std::optional<LobeSample> PowderLobe::sample(const Vec3& wo, float u_choice, const Vec2& u,
                                             const SampledWavelengths& lambda) const {
  if (!(wo.z > 0.0f)) return std::nullopt;
  const PowderSampling& hero = mixtures(wo)[0];
  std::optional<Vec3> wi;
  if (u_choice < hero.p_cone) {
    // Radial CDF of q: 1 - w / sqrt(w^2 + r^2), inverted.
    const float xi = std::min(u.x, 0.99999994f);
    const float r = hero.cone_width * std::sqrt(std::max(0.0f, 1.0f / ((1.0f - xi) * (1.0f - xi)) - 1.0f));
    const float phi = 2.0f * kPi * u.y;
    wi = lift(wo.x + r * std::cos(phi), wo.y + r * std::sin(phi));
  } else if (u_choice < hero.p_cone + hero.p_surface) {
    // Box-Muller: two independent normals from u.
    const float radius = hero.surface_sigma * std::sqrt(-2.0f * std::log(std::max(1.0f - u.x, 1e-30f)));
    const float phi = 2.0f * kPi * u.y;
    wi = lift(-wo.x + radius * std::cos(phi), -wo.y + radius * std::sin(phi));
  } else {
    wi = sample_cosine_hemisphere(u);
  }
  if (!wi || !(wi->z > 0.0f)) return std::nullopt;
  LobeSample s;
  s.wi = *wi;
  s.pdf = pdf(wo, s.wi, lambda);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.value = eval(wo, s.wi, lambda);
  s.has_value = true;
  s.weight = s.value * (s.wi.z / s.pdf);
  return s;
}

SampledSpectrum PowderLobe::albedo_hint(const Vec3& wo, const SampledWavelengths&) const {
  SampledSpectrum a;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const PowderParams<float>& p = params_[i];
    const float mu_o = std::max(std::fabs(wo.z), 1e-4f);
    const float tis = 4.0f * kPi * mu_o / wavelengths_[i].lambda_um;
    const PowderTerms<float> normal = powder_terms(p, wavelengths_[i], Vec3(0, 0, 1), Vec3(wo.x, wo.y, mu_o));
    a[i] = std::max(0.0f, p.volume_amplitude) * kPi * normal.volume() +
           std::max(0.0f, p.surface_amplitude) * tis * tis;
  }
  return a;
}

}  // namespace ochre
