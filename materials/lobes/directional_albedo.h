#pragma once
// Directional albedo of a closure, rho(wo) = integral of f(wo, wi) |cos theta_i| over the whole sphere
// of wi (reflection and transmission), two independent ways: Monte Carlo with the closure's own
// sampler (tests sample() and its weights) and a deterministic product quadrature of eval() (tests
// eval(); delta lobes are invisible to it).

#include <cstdint>
#include <functional>

#include "materials/lobes/closure.h"

namespace ochre {

struct AlbedoEstimate {
  double monte_carlo = 0.0, monte_carlo_se = 0.0;   // mean of the sample weights, standard error
  double quadrature = 0.0, quadrature_error = 0.0;  // fine rule, |fine - coarse|
};

// Lane 0 of the wavelengths. `samples` Monte-Carlo samples from `seed`. `stop`, when given, is asked every
// 2^16 samples whether to stop (Ctrl-C in Python, docs/python.md): when it returns true the estimate ends
// early, incomplete, and the caller discards it.
AlbedoEstimate directional_albedo(const Closure& closure, const Vec3& wo, const SampledWavelengths& lambda,
                                  uint64_t samples, uint64_t seed, const std::function<bool()>& stop = {});

}  // namespace ochre
