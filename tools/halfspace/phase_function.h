#pragma once
// Phase functions of the half-space simulation, normalised to 1 over the sphere (1/sr), as functions of
// the cosine u of the scattering angle (u = +1: straight on, u = -1: straight back).

#include "tools/halfspace/direction.h"
#include "tools/halfspace/random_source.h"

namespace ochre::halfspace {

enum class PhaseFunction { kLambertianSphere, kIsotropic };

// Far-field phase function of a white Lambertian sphere, d'Eon Eq 1:
// p(u) = 2 (sqrt(1 - u^2) - u acos(u)) / (3 pi^2). p(1) = 0, p(-1) = 2 / (3 pi), mean cosine -4/9.
double lambertian_sphere_phase(double u);

double phase_value(PhaseFunction phase, double u);

// New propagation direction after a photon travelling along `d` scatters, simulated from the
// geometry rather than from an inverted CDF (independent of d'Eon Eq 6): the photon hits the sphere
// at a uniformly distributed point of its projected disk, and leaves cosine-distributed about the
// outward normal at that point. The sphere is convex, so the reflected light is never blocked by it.
Direction sample_lambertian_sphere_scattering(const Direction& d, RandomSource& random);

Direction sample_uniform_sphere(RandomSource& random);

Direction sample_phase(PhaseFunction phase, const Direction& d, RandomSource& random);

}  // namespace ochre::halfspace
