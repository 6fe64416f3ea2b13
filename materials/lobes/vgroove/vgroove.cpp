#include "materials/lobes/vgroove/vgroove.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ochre {

VGroove::VGroove(double alpha) : alpha_(alpha) {
  half_opening_ = std::sin(0.5 * alpha);
  depth_ = std::cos(0.5 * alpha);
  if (alpha >= std::numbers::pi) {  // flat: both facets are the plane z = 0
    half_opening_ = 1.0;
    depth_ = 0.0;
  }
  n1_ = {0.0, depth_, half_opening_};
  n2_ = {0.0, -depth_, half_opening_};
  max_reflections_ = std::max(1, static_cast<int>(std::ceil(std::numbers::pi / alpha - 1e-9)));
  if (alpha >= std::numbers::pi) max_reflections_ = 1;
}

VGroovePath VGroove::trace(const Vec3d& e, double y_p) const {
  // Direction in the cross-section, e_perp = (sin theta', cos theta') of Eqs 4-5 (e.z > 0).
  const double norm = std::hypot(e.y, e.z);
  const double sy = e.y / norm, sz = e.z / norm;
  // The sign of y_Q (Eq 6), where the line crosses the horizontal through the apex: y_p - c tan theta'.
  const bool facet1_first = y_p * sz - depth_ * sy < 0.0;
  // Mirror y -> -y so that facet 2 is met first; the unfolded images then lie at increasing angles.
  const double py = facet1_first ? -y_p : y_p;
  const double dy = facet1_first ? sy : -sy, dz = -sz;  // unfolded propagation direction -e_perp
  // Where the line P + t d leaves the unit circle (|P| <= 1, so the larger root is >= 0).
  const double pd = py * dy + depth_ * dz;
  const double pp = py * py + depth_ * depth_;
  const double t = -pd + std::sqrt(std::max(0.0, pd * pd + 1.0 - pp));
  const double hy = py + t * dy, hz = depth_ + t * dz;
  // Its angle from the z axis towards y lies in [alpha/2, alpha/2 + pi) (Eq 12 with gamma_H in [0, 2pi)).
  double gamma = std::atan2(hy, hz);
  if (gamma < 0.0) gamma += 2.0 * std::numbers::pi;
  // Eq 13: one reflection per facet image crossed.
  int m = static_cast<int>(std::floor(gamma / alpha_ - 0.5)) + 1;
  m = std::clamp(m, 1, max_reflections_);

  VGroovePath path;
  path.first_facet = facet1_first ? 1 : 2;
  Vec3d d = -e;
  for (int j = 1; j <= m; ++j) d = reflect(d, facet_normal(facet_of_reflection(path, j)));
  // A ray through a rim image is where two counts meet; rounding may pick the one that still heads into
  // the cavity: then it reflects once more.
  while (d.z <= 0.0 && m < max_reflections_) {
    ++m;
    d = reflect(d, facet_normal(facet_of_reflection(path, m)));
  }
  path.reflections = m;
  path.exit = d;
  return path;
}

std::vector<double> VGroove::breakpoints(const Vec3d& e) const {
  const double h = half_opening_, c = depth_;
  const double tan_theta = e.y / e.z;  // tan theta' (Eq 5)
  std::vector<double> y = {-h, h};
  auto add = [&](double v) {
    if (v > -h && v < h) y.push_back(v);
  };
  // A line along -e_perp through the point V meets the opening's line z = c at V_y + (c - V_z) tan theta'.
  add(c * tan_theta);  // the apex
  for (int k = 0; k <= max_reflections_; ++k) {
    const double beta = 0.5 * alpha_ + k * alpha_;  // rim images at +-beta on the unit circle
    const double sb = std::sin(beta), cb = std::cos(beta);
    add(sb + (c - cb) * tan_theta);
    add(-sb + (c - cb) * tan_theta);
  }
  std::sort(y.begin(), y.end());
  y.erase(std::unique(y.begin(), y.end()), y.end());
  return y;
}

}  // namespace ochre
