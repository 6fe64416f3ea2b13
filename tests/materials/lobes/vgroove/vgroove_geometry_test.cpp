// The V-groove path (reflection count, first facet, exit direction) against an independent explicit
// tracer of the real cavity in the cross-section, including the hard cases: alpha down to 1 degree and
// up to 180, grazing directions, and rays through the apex and the rim images.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove.h"
#include "materials/lobes/vgroove/vgroove_reference.h"

namespace ochre::test::vgroove_geometry_test {
namespace {

struct ExplicitPath {
  int reflections = 0;
  int first_facet = 0;
  Vec3d exit;
};

// Traces the ray entering at (y_p, depth) along -e through the two real facet segments (apex at the
// origin, rim vertices (-+sin(a/2), cos(a/2))), reflecting at each hit, until it leaves above the opening.
ExplicitPath trace_explicitly(const VGroove& g, const Vec3d& e, double y_p) {
  ExplicitPath out;
  Vec3d p{0.0, y_p, g.depth()}, d = -e;
  const double h = g.half_opening(), c = g.depth();
  int last = 0;
  for (int bounce = 0; bounce < 4 * g.max_reflections() + 4; ++bounce) {
    double best_t = INFINITY;
    int best = 0;
    for (int facet : {1, 2}) {
      if (facet == last) continue;  // a ray cannot hit the plane it just left
      const Vec3d rim = facet == 1 ? Vec3d(0.0, -h, c) : Vec3d(0.0, h, c);
      const Vec3d& n = g.facet_normal(facet);
      const double denom = dot(d, n);
      if (!(denom < 0.0)) continue;
      const double t = -dot(p, n) / denom;  // the facet's plane passes through the apex (origin)
      if (!(t > 0.0)) continue;
      const Vec3d q = p + d * t;
      // Within the segment from the apex to the rim: the projection on the rim direction in [0, 1].
      const double s = (q.y * rim.y + q.z * rim.z) / (rim.y * rim.y + rim.z * rim.z);
      if (s < -1e-12 || s > 1.0 + 1e-12) continue;
      if (t < best_t) best_t = t, best = facet;
    }
    if (best == 0) break;
    p = p + d * best_t;
    d = reflect(d, g.facet_normal(best));
    if (out.reflections == 0) out.first_facet = best;
    ++out.reflections;
    last = best;
  }
  out.exit = d;
  return out;
}

TEST(VGrooveGeometry, ReflectionCountFirstFacetAndExitAgreeWithAnExplicitTracer) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double alpha_deg : {1.0, 2.0, 5.0, 30.0, 45.0, 60.0, 90.0, 100.0, 150.0, 179.9}) {
    const VGroove g(alpha_deg * kDegD);
    int disagreements = 0;
    const int rays = 20000;
    for (int i = 0; i < rays; ++i) {
      const Vec3d e = groove_direction(std::acos(u(rng)), 2.0 * std::numbers::pi * u(rng));
      const double y_p = (2.0 * u(rng) - 1.0) * g.half_opening();
      const VGroovePath path = g.trace(e, y_p);
      const ExplicitPath want = trace_explicitly(g, e, y_p);
      if (path.reflections != want.reflections || path.first_facet != want.first_facet ||
          length(path.exit - want.exit) > 1e-9)
        ++disagreements;
      ASSERT_GE(path.reflections, 1);
      ASSERT_LE(path.reflections, g.max_reflections());
      ASSERT_GT(path.exit.z, 0.0) << "alpha " << alpha_deg;
      ASSERT_NEAR(length(path.exit), 1.0, 1e-12);
    }
    // Rays within rounding of a rim image may legitimately differ by one reflection (a set of measure 0).
    EXPECT_LE(disagreements, 2) << "alpha " << alpha_deg;
  }
}

TEST(VGrooveGeometry, FlatSurfaceIsOneMirrorReflection) {
  const VGroove g(std::numbers::pi);
  const Vec3d e = groove_direction(40 * kDegD, 25 * kDegD);
  for (double y : {-1.0, -0.3, 0.0, 0.7, 1.0}) {
    const VGroovePath path = g.trace(e, y);
    EXPECT_EQ(path.reflections, 1);
    EXPECT_NEAR(length(path.exit - Vec3d(-e.x, -e.y, e.z)), 0.0, 1e-15);
  }
}

TEST(VGrooveGeometry, NinetyDegreeGrooveSeenAcrossIsARetroreflector) {
  // Two reflections off perpendicular facets reverse the cross-section direction: a corner reflector.
  const VGroove g(90 * kDegD);
  const Vec3d e = groove_direction(20 * kDegD, 0.0);
  const VGroovePath path = g.trace(e, 0.3 * g.half_opening());
  EXPECT_EQ(path.reflections, 2);
  EXPECT_NEAR(length(path.exit - Vec3d(e.x, e.y, e.z)), 0.0, 1e-12);
}

TEST(VGrooveGeometry, HardCasesStayFiniteAndConsistent) {
  for (double alpha_deg : {1.0, 2.0, 5.0, 179.9, 180.0}) {
    const VGroove g(alpha_deg * kDegD);
    for (double theta_deg : {0.0, 1e-6, 30.0, 60.0, 89.0, 89.9, 89.99}) {
      for (double phi_deg : {0.0, 1e-7, 30.0, 89.9999, 90.0, 135.0, 180.0}) {
        const Vec3d e = groove_direction(theta_deg * kDegD, phi_deg * kDegD);
        // Exactly at every breakpoint (rays through the apex and the rim images) and between them.
        const std::vector<double> y = g.breakpoints(e);
        for (size_t i = 0; i < y.size(); ++i) {
          for (double y_p : {y[i], i + 1 < y.size() ? 0.5 * (y[i] + y[i + 1]) : y[i]}) {
            const VGroovePath path = g.trace(e, y_p);
            ASSERT_GE(path.reflections, 1);
            ASSERT_LE(path.reflections, g.max_reflections());
            ASSERT_TRUE(std::isfinite(path.exit.x) && std::isfinite(path.exit.y) &&
                        std::isfinite(path.exit.z));
            ASSERT_GE(path.exit.z, 0.0) << alpha_deg << " " << theta_deg << " " << phi_deg << " " << y_p;
            // The x component never changes; the speed stays 1.
            ASSERT_EQ(path.exit.x, -e.x);
            ASSERT_NEAR(length(path.exit), 1.0, 1e-12);
          }
        }
        const DirectionalReflectance r = directional_reflectance(
            g, e, ChainModel::kRigorous, std::vector<FacetIndex>{FacetIndex::conductor(4.073, 0.028)});
        ASSERT_TRUE(std::isfinite(r.reflectance[0]));
        ASSERT_GE(r.reflectance[0], 0.0);
        ASSERT_LE(r.reflectance[0], 1.0);
      }
    }
  }
}

TEST(VGrooveGeometry, TheResponseIsConstantBetweenBreakpoints) {
  // Every ray of an interval follows the midpoint's facet sequence: check the ends of each interval
  // (just inside) against the midpoint.
  const VGroove g(37 * kDegD);
  for (double theta_deg : {10.0, 45.0, 80.0}) {
    for (double phi_deg : {0.0, 33.0, 70.0}) {
      const Vec3d e = groove_direction(theta_deg * kDegD, phi_deg * kDegD);
      const std::vector<double> y = g.breakpoints(e);
      for (size_t i = 0; i + 1 < y.size(); ++i) {
        const double w = y[i + 1] - y[i];
        const VGroovePath mid = g.trace(e, y[i] + 0.5 * w);
        for (double f : {1e-6, 1.0 - 1e-6}) {
          const VGroovePath p = g.trace(e, y[i] + f * w);
          EXPECT_EQ(p.reflections, mid.reflections);
          EXPECT_EQ(p.first_facet, mid.first_facet);
        }
      }
    }
  }
}

}  // namespace
}  // namespace ochre::test::vgroove_geometry_test
