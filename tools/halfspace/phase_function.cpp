#include "tools/halfspace/phase_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ochre::halfspace {

namespace {

constexpr double kPi = std::numbers::pi;

// Orthonormal basis (t, b, n) around unit n (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited").
void basis_around(const Direction& n, Direction& t, Direction& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

Direction combine(const Direction& t, const Direction& b, const Direction& n, double u, double v, double w) {
  return {u * t.x + v * b.x + w * n.x, u * t.y + v * b.y + w * n.y, u * t.z + v * b.z + w * n.z};
}

// Keeps rounding from accumulating over walks of up to millions of collisions.
Direction normalized(const Direction& d) {
  const double inv = 1.0 / std::sqrt(dot(d, d));
  return {d.x * inv, d.y * inv, d.z * inv};
}

// Uniform point of the unit disk, by rejection from the square (no trigonometry: the walk's hot path).
void uniform_disk(RandomSource& random, double& u, double& v) {
  do {
    u = 2.0 * random.uniform() - 1.0;
    v = 2.0 * random.uniform() - 1.0;
  } while (u * u + v * v >= 1.0);
}

// Uniform on the unit sphere (Marsaglia 1972: a uniform disk point lifted onto the sphere).
Direction uniform_sphere_marsaglia(RandomSource& random) {
  double u, v;
  uniform_disk(random, u, v);
  const double s = u * u + v * v, root = 2.0 * std::sqrt(1.0 - s);
  return {u * root, v * root, 1.0 - 2.0 * s};
}

}  // namespace

double lambertian_sphere_phase(double u) {
  u = std::clamp(u, -1.0, 1.0);
  return 2.0 * (std::sqrt(1.0 - u * u) - u * std::acos(u)) / (3.0 * kPi * kPi);
}

double phase_value(PhaseFunction phase, double u) {
  return phase == PhaseFunction::kIsotropic ? 1.0 / (4.0 * kPi) : lambertian_sphere_phase(u);
}

Direction sample_lambertian_sphere_scattering(const Direction& d, RandomSource& random) {
  Direction t, b;
  basis_around(d, t, b);
  // Hit point: (a, c) uniform on the projected disk; the lit hemisphere faces -d.
  double a, c;
  uniform_disk(random, a, c);
  const double depth = std::sqrt(std::max(0.0, 1.0 - a * a - c * c));
  const Direction normal = combine(t, b, d, a, c, -depth);
  // Lambertian reflection, cosine-distributed about the normal: the direction of normal + u with u uniform
  // on the unit sphere. The points normal + u are uniform on the unit sphere centred at `normal`, which
  // touches the tangent plane at the hit point; seen from there its area element is 4 cos(theta) d(omega),
  // so the direction has density cos(theta) / pi.
  for (;;) {
    const Direction u = uniform_sphere_marsaglia(random);
    const Direction sum{normal.x + u.x, normal.y + u.y, normal.z + u.z};
    if (dot(sum, sum) > 1e-12) return normalized(sum);
  }
}

Direction sample_uniform_sphere(RandomSource& random) {
  return uniform_sphere_marsaglia(random);
}

Direction sample_phase(PhaseFunction phase, const Direction& d, RandomSource& random) {
  return phase == PhaseFunction::kIsotropic ? sample_uniform_sphere(random)
                                            : sample_lambertian_sphere_scattering(d, random);
}

}  // namespace ochre::halfspace
