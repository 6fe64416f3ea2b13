#pragma once
// Chi-square goodness-of-fit test of a Lobe's sample() against its pdf(), for any lobe (the
// method of Mitsuba's chi2 tests): sampled directions are histogrammed over cells of equal solid
// angle in (cos theta, phi) on the whole sphere; pdf() is integrated over each cell numerically
// (composite Simpson) for the expected counts; cells with expected count < 5 are pooled; the
// statistic's p-value comes from the regularized incomplete gamma function.
// Each sample is also checked: weight == eval |cos| / pdf (per wavelength) and pdf == pdf(), both
// to 1e-4 relative. Delta samples are counted but not histogrammed.

#include <cstdint>
#include <string>

#include "materials/lobes/lobe.h"

namespace ochre {

struct Chi2Result {
  double statistic = 0.0;
  int degrees_of_freedom = 0;
  double p_value = 0.0;  // 0 when a sample fell where pdf() integrates to 0
  int samples_histogrammed = 0;
  int samples_failed = 0;          // sample() returned nothing
  int samples_delta = 0;           // delta samples (not histogrammed)
  int samples_in_empty_cells = 0;  // in cells whose expected count is 0
  int weight_mismatches = 0;       // weight != eval |cos| / pdf beyond 1e-4 relative
  int pdf_mismatches = 0;          // sample's pdf != pdf(wo, wi) beyond 1e-4 relative
  double max_weight_error = 0.0;   // largest relative weight error seen
  std::string summary() const;
};

Chi2Result chi2_test(const Lobe& lobe, const Vec3& wo, const SampledWavelengths& lambda, int theta_bins = 40,
                     int phi_bins = 80, int samples = 1'000'000, uint64_t seed = 0x5eed);

// Regularized upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a) (the chi-square p-value
// with k degrees of freedom is Q(k/2, statistic/2)).
double regularized_gamma_q(double a, double x);

// Per-test significance for `tests` independent tests at overall level alpha (Sidak):
// 1 - (1 - alpha)^(1/tests).
double sidak_significance(double alpha, int tests);

}  // namespace ochre
