#pragma once
// Monte-Carlo reference for the BRDF of a homogeneous semi-infinite medium (the half-space z < 0) of
// unit extinction with single-scattering albedo c and a given phase function: the ground truth for the
// analytic Lambertian-sphere BRDF (d'Eon, "An analytic BRDF for materials with spherical Lambertian
// scatterers"). Independent of the renderer's materials on purpose.
//
// Estimator. A collimated beam arrives along -wi (mu_i = wi.z > 0). Photons enter at N per unit
// surface area, so the irradiance is E = N (unit power each). Exponential free flights give the
// collision density C(t) per unit volume at depth t. Each collision emits c C p(d.wo) per unit volume
// and solid angle toward wo (d = propagation direction before the collision), attenuated by exp(-t/mu_o)
// on the way out; integrating along the exit ray (ds = dt / mu_o) gives the exiting radiance
// L(wo) = int c C(t) p(d.wo) exp(-t/mu_o) dt / mu_o, and f = L / E is therefore the expectation per
// entering photon of
//     sum over collisions k of  w_k c p(d_k . wo) exp(-t_k / mu_o) / mu_o,
// with w_k the photon's weight arriving at collision k (no cosine factor; 1/sr). For the first
// collision, t_1 = s mu_i with s ~ Exp(1) and d_1 = -wi, whose expectation is c p(-wi.wo) / (mu_i + mu_o):
// the closed-form single scattering (d'Eon Eq 17). Absorption: the weight is multiplied by c after each
// collision, with Russian roulette below a threshold (unbiased).
//
// Results are deterministic for a given seed whatever the thread count: paths are split into fixed
// blocks, each with its own random stream, and blocks are summed in order.

#include <cstdint>
#include <vector>

#include "tools/halfspace/direction.h"
#include "tools/halfspace/phase_function.h"

namespace ochre::halfspace {

struct Estimate {
  double mean = 0.0;
  double standard_error = 0.0;  // of the mean, from the per-path sample variance
};

struct HalfspaceResult {
  Estimate single;    // first collision only
  Estimate multiple;  // second and later collisions
  Estimate total;     // per-path sum of both (its error includes their correlation)
};

struct SimulationOptions {
  PhaseFunction phase = PhaseFunction::kLambertianSphere;
  // Walks are cut after this many collisions; their weight is reported as truncated. Only matters near
  // c = 1, where a walk in a conservative half-space escapes with probability 1 but its length has
  // infinite mean (survival to n collisions ~ n^-1/2): the cut loses a fraction ~ 1/sqrt(pi n) of the
  // albedo.
  uint64_t max_collisions = 1'000'000;
  unsigned threads = 1;  // 0 = std::thread::hardware_concurrency()
};

struct GridResult {
  std::vector<HalfspaceResult> brdf;  // one per outgoing direction, in the order given
  Estimate albedo;                    // escaping weight per entering photon (counted, not estimated)
  double truncated_weight = 0.0;      // weight per entering photon still in flight at the cut
  uint64_t paths = 0;
  uint64_t collisions = 0;  // total over all paths (a cost figure)
};

// BRDF f(wi, wo) for every wo of `outgoing` at once: each walk started from wi scores every outgoing
// direction at every collision. All directions are unit vectors; wi.z must be > 0. An outgoing direction
// with z <= 0 gets f = 0.
GridResult simulate_brdf_grid(double c, const Direction& wi, const std::vector<Direction>& outgoing,
                              uint64_t paths, uint64_t seed, const SimulationOptions& options = {});

// One outgoing direction.
HalfspaceResult simulate_brdf(double c, const Direction& wi, const Direction& wo, uint64_t paths,
                              uint64_t seed, const SimulationOptions& options = {});

}  // namespace ochre::halfspace
