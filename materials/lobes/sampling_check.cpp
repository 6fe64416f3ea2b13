#include "materials/lobes/sampling_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "materials/core/pcg32.h"
#include "materials/core/pi.h"

namespace ochre {

namespace {

constexpr double kMinExpected = 5.0;  // pool cells expecting fewer samples (the usual chi-square rule)
constexpr double kRelativeTolerance = 1e-4;

double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::max(std::abs(reference), 1e-12);
}

Vec3 direction(double z, double phi) {
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
          static_cast<float>(z)};
}

// Integral of pdf over the cell [z0, z1] x [phi0, phi1]; dw = dz dphi on the sphere, so the
// pdf is integrated as is. Composite Simpson's rule with 6 intervals per dimension.
double integrate_cell(const Lobe& lobe, const Vec3& wo, const SampledWavelengths& lambda, double z0,
                      double z1, double phi0, double phi1) {
  constexpr int kIntervals = 6;
  constexpr double kWeights[kIntervals + 1] = {1, 4, 2, 4, 2, 4, 1};
  const double hz = (z1 - z0) / kIntervals, hphi = (phi1 - phi0) / kIntervals;
  double sum = 0.0;
  for (int a = 0; a <= kIntervals; ++a)
    for (int b = 0; b <= kIntervals; ++b)
      sum += kWeights[a] * kWeights[b] * lobe.pdf(wo, direction(z0 + a * hz, phi0 + b * hphi), lambda);
  return sum * (hz / 3.0) * (hphi / 3.0);
}

// Series for the lower function: P(a, x) = e^-x x^a / Gamma(a) * sum_n x^n / (a (a+1) ... (a+n)).
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction for the upper function, evaluated with the modified Lentz method:
// Q(a, x) = e^-x x^a / Gamma(a) * 1 / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) / (x + 5 - a - ...))).
double gamma_q_continued_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

struct Cell {
  double observed = 0.0, expected = 0.0;
};

void add_term(const Cell& c, Chi2Result& r) {
  r.statistic += (c.observed - c.expected) * (c.observed - c.expected) / c.expected;
  ++r.degrees_of_freedom;
}

void check_sample(const Lobe& lobe, const Vec3& wo, const LobeSample& s, const SampledWavelengths& lambda,
                  Chi2Result& r) {
  const float pdf = lobe.pdf(wo, s.wi, lambda);
  if (!(pdf > 0.0f) || relative_error(s.pdf, pdf) > kRelativeTolerance) ++r.pdf_mismatches;
  if (!(pdf > 0.0f)) {
    ++r.weight_mismatches;
    return;
  }
  const SampledSpectrum expected = lobe.eval(wo, s.wi, lambda) * (abs_cos_theta(s.wi) / pdf);
  double worst = 0.0;
  for (int k = 0; k < kSpectrumSamples; ++k)
    worst = std::max(worst, relative_error(s.weight[k], expected[k]));
  r.max_weight_error = std::max(r.max_weight_error, worst);
  if (!(worst <= kRelativeTolerance)) ++r.weight_mismatches;
}

}  // namespace

double regularized_gamma_q(double a, double x) {
  if (x <= 0.0) return 1.0;
  if (x < a + 1.0) return 1.0 - gamma_p_series(a, x);
  return gamma_q_continued_fraction(a, x);
}

double sidak_significance(double alpha, int tests) {
  return 1.0 - std::pow(1.0 - alpha, 1.0 / tests);
}

Chi2Result chi2_test(const Lobe& lobe, const Vec3& wo, const SampledWavelengths& lambda, int theta_bins,
                     int phi_bins, int samples, uint64_t seed) {
  Chi2Result r;
  const double dz = 2.0 / theta_bins, dphi = kTwoPiD / phi_bins;
  std::vector<Cell> cells(static_cast<size_t>(theta_bins) * phi_bins);

  Pcg32 rng(seed);
  for (int i = 0; i < samples; ++i) {
    const float u_choice = rng.next_float();
    const Vec2 u{rng.next_float(), rng.next_float()};
    const std::optional<LobeSample> s = lobe.sample(wo, u_choice, u, lambda);
    if (!s) {
      ++r.samples_failed;
      continue;
    }
    if (s->delta) {
      ++r.samples_delta;
      continue;
    }
    check_sample(lobe, wo, *s, lambda, r);
    const double z = std::clamp(static_cast<double>(s->wi.z), -1.0, 1.0);
    double phi = std::atan2(s->wi.y, s->wi.x);
    if (phi < 0.0) phi += kTwoPiD;
    const int ti = std::min(static_cast<int>((z + 1.0) / dz), theta_bins - 1);
    const int pj = std::min(static_cast<int>(phi / dphi), phi_bins - 1);
    cells[static_cast<size_t>(ti) * phi_bins + pj].observed += 1.0;
    ++r.samples_histogrammed;
  }

  for (int ti = 0; ti < theta_bins; ++ti)
    for (int pj = 0; pj < phi_bins; ++pj)
      cells[static_cast<size_t>(ti) * phi_bins + pj].expected =
          samples *
          integrate_cell(lobe, wo, lambda, -1.0 + ti * dz, -1.0 + (ti + 1) * dz, pj * dphi, (pj + 1) * dphi);

  // Pool the cells with small expected counts (smallest first) until the pool reaches the minimum.
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.expected < b.expected; });
  Cell pool;
  for (const Cell& c : cells) {
    if (c.expected <= 0.0) {
      r.samples_in_empty_cells += static_cast<int>(c.observed);
      continue;
    }
    if (c.expected < kMinExpected || (pool.expected > 0.0 && pool.expected < kMinExpected)) {
      pool.observed += c.observed;
      pool.expected += c.expected;
    } else {
      add_term(c, r);
    }
  }
  if (pool.expected > 0.0) add_term(pool, r);
  r.degrees_of_freedom -= 1;  // the counts sum to the number of samples

  if (r.samples_in_empty_cells > 0 || r.degrees_of_freedom < 1)
    r.p_value = 0.0;
  else
    r.p_value = regularized_gamma_q(0.5 * r.degrees_of_freedom, 0.5 * r.statistic);
  return r;
}

std::string Chi2Result::summary() const {
  std::ostringstream s;
  s << "chi2 = " << statistic << ", dof = " << degrees_of_freedom << ", p = " << p_value
    << "; samples: " << samples_histogrammed << " histogrammed, " << samples_failed << " failed, "
    << samples_delta << " delta, " << samples_in_empty_cells << " in cells of zero pdf; weight mismatches "
    << weight_mismatches << " (max rel. error " << max_weight_error << "), pdf mismatches " << pdf_mismatches;
  return s.str();
}

}  // namespace ochre
