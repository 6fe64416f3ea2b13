#include "renderer/geometry/accel.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

#include "renderer/shapes/mesh_import.h"
#include "renderer/shapes/procedural_shapes.h"
#include "spectra/input_error.h"
#include "support/test_paths.h"

namespace ochre::accel_test {
namespace {

struct Random {
  std::mt19937 engine{12345};
  float uniform(float lo = 0, float hi = 1) { return std::uniform_real_distribution<float>(lo, hi)(engine); }
  Vec3 direction() {  // uniform on the sphere
    const float z = uniform(-1, 1), phi = uniform(0, 2 * kPi), r = std::sqrt(std::max(0.0f, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  Vec3 in_ball(float radius) { return direction() * (radius * std::cbrt(uniform())); }
};

Vec3 winding_normal(const Mesh& m, uint32_t t) {
  const Vec3 &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
             &c = m.positions[m.indices[3 * t + 2]];
  return cross(b - a, c - a);
}

// Builds the mesh list by moving (a braced initializer list would copy the meshes and drop the
// spare position capacity that lets Accel share them with Embree).
template <typename... Meshes>
std::vector<Mesh> mesh_list(Meshes&&... meshes) {
  std::vector<Mesh> list;
  (list.push_back(std::move(meshes)), ...);
  return list;
}

Mesh placed(Mesh mesh, const Transform& t) {
  mesh.transform(t);
  return mesh;
}

TEST(Accel, RayHitsPlaneAtExactDistance) {
  std::vector<Mesh> meshes = mesh_list(make_plane({2, 2}));
  const Accel accel(meshes);
  const Ray ray{{0.3f, 0.2f, 5}, {0, 0, -1}};
  const auto hit = accel.intersect(ray);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, 5.0f);
  EXPECT_EQ(hit->mesh, 0u);
  // Embree's Ng is the winding normal, whichever side the ray comes from.
  EXPECT_EQ(normalize(hit->ng), Vec3(0, 0, 1));
  const auto below = accel.intersect({{0.3f, 0.2f, -2}, {0, 0, 1}});
  ASSERT_TRUE(below);
  EXPECT_EQ(below->t, 2.0f);
  EXPECT_EQ(normalize(below->ng), Vec3(0, 0, 1));

  const SurfacePoint sp = surface_point(meshes, *hit, ray);
  EXPECT_NEAR(length(sp.p - Vec3(0.3f, 0.2f, 0)), 0.0f, 1e-7f);
  EXPECT_EQ(sp.ng, Vec3(0, 0, 1));
  EXPECT_EQ(sp.ns, Vec3(0, 0, 1));
  ASSERT_TRUE(sp.has_uv);
  EXPECT_NEAR(sp.uv.x, 0.65f, 1e-6f);
  EXPECT_NEAR(sp.uv.y, 0.6f, 1e-6f);
  EXPECT_NEAR(length(sp.dpdu - Vec3(2, 0, 0)), 0.0f, 1e-6f);  // u spans 2 units along x
  EXPECT_NEAR(sp.area_scale_uv, 4.0f, 1e-6f);                 // area 4 per unit uv square
  EXPECT_FALSE(sp.has_colour);
  // tmax before the plane, tmin past it, and pointing away all miss.
  EXPECT_FALSE(accel.intersect({{0.3f, 0.2f, 5}, {0, 0, -1}, 0, 4.9f}));
  EXPECT_FALSE(accel.intersect({{0.3f, 0.2f, 5}, {0, 0, -1}, 5.1f}));
  EXPECT_FALSE(accel.intersect({{0.3f, 0.2f, 5}, {0, 0, 1}}));
  EXPECT_FALSE(accel.intersect({{3, 0, 5}, {0, 0, -1}}));
  EXPECT_EQ(accel.copied_vertex_buffers(), 0u);
}

TEST(Accel, MeshIndexIsGeometryIdAndHitsMatchTheWinding) {
  std::vector<Mesh> meshes;
  meshes.push_back(placed(make_plane({1, 1}), Transform::translate({0, 0, -10})));
  meshes.push_back(Mesh{});  // empty meshes keep their slot
  meshes.push_back(
      placed(make_sphere(1, 24), Transform::translate({0, 0, 3}) * Transform::scale({1, 2, 0.5f})));
  const Accel accel(meshes);
  Random random;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 origin = Vec3(0, 0, 3) + random.direction() * 10.0f;
    const Vec3 target = Vec3(0, 0, 3) + random.in_ball(0.4f);
    const Ray ray{origin, target - origin};
    const auto hit = accel.intersect(ray);
    ASSERT_TRUE(hit);
    ASSERT_EQ(hit->mesh, 2u);
    ASSERT_EQ(accel.copied_vertex_buffers(), 0u);
    const Vec3 expected = winding_normal(meshes[2], hit->triangle);
    EXPECT_NEAR(length(hit->ng - expected), 0.0f, 1e-4f * length(expected));
    // The barycentric point equals the ray point.
    const SurfacePoint sp = surface_point(meshes, *hit, ray);
    EXPECT_NEAR(length(sp.p - (ray.origin + ray.dir * hit->t)), 0.0f, 1e-5f);
    EXPECT_LT(dot(ray.dir, sp.ng), 0.0f);  // from outside, the outward winding normal faces the ray
    EXPECT_NEAR(length(sp.ns), 1.0f, 1e-5f);
  }
}

TEST(Accel, OccludedAgreesWithIntersect) {
  std::vector<Mesh> meshes =
      mesh_list(make_sphere(1, 16), placed(make_plane({4, 4}), Transform::translate({0, 0, -1.5f})),
                placed(make_disk(0.7f, 32),
                       Transform::translate({1.2f, 0.3f, 0.4f}) * Transform::rotate(60, {1, 1, 0})));
  const Accel accel(meshes);
  Random random;
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ray ray{random.in_ball(3), random.direction(), random.uniform(0, 0.5f), random.uniform(0, 4)};
    const bool hit = accel.intersect(ray).has_value();
    hits += hit;
    ASSERT_EQ(accel.occluded(ray), hit) << i;
  }
  EXPECT_GT(hits, 2000);
  EXPECT_LT(hits, 18000);
}

TEST(Accel, TraversalTimingCountsOnlyWhileOnAndResets) {
  std::vector<Mesh> meshes = mesh_list(make_sphere(1, 64));
  Accel accel(meshes);
  Random random;
  const auto trace = [&](int n) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) {
      const Ray ray{random.in_ball(3), random.direction()};
      (void)accel.intersect(ray);
      (void)accel.occluded(ray);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  trace(1000);
  EXPECT_EQ(accel.traversal_seconds(), 0.0);  // off by default: nothing counted
  accel.set_traversal_timing(true);
  const double wall = trace(20000);
  const double inside = accel.traversal_seconds();
  EXPECT_GT(inside, 0.0);
  EXPECT_LT(inside, wall * 1.05);  // the queries are part of the loop's time
  accel.set_traversal_timing(false);
  trace(1000);
  EXPECT_NEAR(accel.traversal_seconds(), inside, 0.05 * inside + 1e-4);  // off: no more counting
  accel.set_traversal_timing(true);
  EXPECT_LT(accel.traversal_seconds(), 0.5 * inside + 1e-6);  // switching on resets the counters
}

// Rays aimed exactly at the diagonal that the plane's two triangles share must hit one of them.
TEST(Accel, RaysAtASharedEdgeNeverSlipThrough) {
  const Transform tilt = Transform::translate({3, -7, 11}) * Transform::rotate(29, {0.3f, 1, 0.2f});
  for (const Transform& to_world : {Transform::identity(), tilt}) {
    std::vector<Mesh> meshes = mesh_list(placed(make_plane({2, 2}), to_world));
    const Accel accel(meshes);
    const Vec3 a = to_world.point({-1, -1, 0}), b = to_world.point({1, 1, 0});  // the shared edge
    Random random;
    int misses = 0;
    for (int i = 0; i < 100000; ++i) {
      const float s = random.uniform(0.001f, 0.999f);
      const Vec3 target = a + (b - a) * s;
      const Vec3 origin = target + random.direction() * random.uniform(0.01f, 100.0f);
      if (!accel.intersect({origin, target - origin, 0, 2})) ++misses;
    }
    EXPECT_EQ(misses, 0);
  }
}

TEST(Accel, SphereMeshIsWatertight) {
  std::vector<Mesh> meshes = mesh_list(placed(
      make_sphere(1, 32), Transform::translate({0.3f, -0.2f, 1.1f}) * Transform::scale({1.7f, 1.7f, 1.7f})));
  const Accel accel(meshes);
  Random random;
  int misses = 0, wrong_side = 0;
  for (int i = 0; i < 100000; ++i) {
    const Ray ray{Vec3(0.3f, -0.2f, 1.1f) + random.in_ball(1.5f), random.direction()};
    const auto hit = accel.intersect(ray);
    if (!hit) {
      ++misses;
    } else if (dot(hit->ng, ray.dir) <= 0) {
      ++wrong_side;
    }
  }
  EXPECT_EQ(misses, 0);
  EXPECT_EQ(wrong_side, 0);
}

// Spawned rays never hit the triangle they leave, at any scale.
TEST(Accel, OffsetOriginsAvoidSelfIntersection) {
  for (float scale : {1e-3f, 1.0f, 1e3f}) {
    const Vec3 centre = Vec3(0.5f, -3, 7) * scale * 10.0f;
    std::vector<Mesh> meshes = mesh_list(placed(
        make_sphere(1, 48), Transform::translate(Vec3d(centre)) * Transform::scale({scale, scale, scale})));
    const Accel accel(meshes);
    Random random;
    int self_hits = 0, escaped_inward = 0, blocked_outward = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 origin = centre + random.direction() * (5 * scale);
      const Ray ray{origin, centre + random.in_ball(0.8f * scale) - origin};
      const auto hit = accel.intersect(ray);
      ASSERT_TRUE(hit);
      const SurfacePoint sp = surface_point(meshes, *hit, ray);
      // Outward: a convex polyhedron cannot be hit again.
      Vec3 out = random.direction();
      if (dot(out, sp.ng) < 0) out = -out;
      if (accel.occluded(spawn_ray(sp, sp.ng, out))) ++blocked_outward;
      // Inward: must hit another triangle on the far side.
      const Vec3 in = -out;
      const auto next = accel.intersect(spawn_ray(sp, sp.ng, in));
      if (!next) {
        ++escaped_inward;
      } else if (next->triangle == hit->triangle) {
        ++self_hits;
      }
    }
    EXPECT_EQ(blocked_outward, 0) << "scale " << scale;
    EXPECT_EQ(escaped_inward, 0) << "scale " << scale;
    EXPECT_EQ(self_hits, 0) << "scale " << scale;
  }
}

TEST(Accel, OffsetOriginsRoundAwayFromZeroCoordinates) {
  // A point on the plane z = 0 with an exact z: the origin steps off to the side of the direction, by a
  // tiny but non-zero amount, from +0 and from -0 alike.
  for (float zero : {0.0f, -0.0f}) {
    const Vec3 up = offset_ray_origin({1, 2, zero}, {0, 0, 0}, {0, 0, 1}, {0, 0, 1});
    const Vec3 down = offset_ray_origin({1, 2, zero}, {0, 0, 0}, {0, 0, 1}, {0, 0, -1});
    EXPECT_GT(up.z, 0.0f);
    EXPECT_LT(up.z, 1e-19f);
    EXPECT_LT(down.z, 0.0f);
    EXPECT_GT(down.z, -1e-19f);
    EXPECT_EQ(up.x, 1.0f);
  }
}

TEST(Accel, OffsetIsTinyAndOnTheSideOfTheDirection) {
  const Vec3 p{100, -0.01f, 2};
  const Vec3 error{3e-5f, 1e-8f, 1e-6f};
  const Vec3 up = offset_ray_origin(p, error, {0, 0, 3}, {0.2f, 0, 1});
  const Vec3 down = offset_ray_origin(p, error, {0, 0, 3}, {0.2f, 0, -1});
  EXPECT_GT(up.z, p.z + 1e-6f * 0.99f);
  EXPECT_LT(down.z, p.z - 1e-6f * 0.99f);
  EXPECT_EQ(up.x, p.x);  // no offset along axes where the normal is zero
  EXPECT_EQ(up.y, p.y);
  EXPECT_LT(up.z - p.z, 1e-5f);
}

// A triangle in a coordinate plane has exact points (error bound 0 across the plane): the origin must
// still leave the plane, or Embree finds the triangle again at t = 0.
TEST(Accel, OffsetOriginsLeaveAxisAlignedPlanesThroughTheOrigin) {
  for (float z : {0.0f, 5.0f}) {
    Mesh plane;
    plane.positions = {{-20, -20, z}, {20, -20, z}, {20, 20, z}, {-20, 20, z}};
    plane.indices = {0, 1, 2, 0, 2, 3};
    std::vector<Mesh> meshes{plane};
    const Accel accel(meshes);
    Random random;
    int self_hits = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vec3 target{(random.uniform() - 0.5f) * 30, (random.uniform() - 0.5f) * 30, z};
      const Ray ray{target + Vec3(16, 28, 38), Vec3(-16, -28, -38)};
      const auto hit = accel.intersect(ray);
      ASSERT_TRUE(hit);
      const SurfacePoint sp = surface_point(meshes, *hit, ray);
      const Vec3 mirrored{ray.dir.x, ray.dir.y, -ray.dir.z};
      if (accel.occluded(spawn_ray(sp, sp.ng, mirrored))) ++self_hits;
    }
    EXPECT_EQ(self_hits, 0) << "z " << z;
  }
}

// A huge tilted mirror: a point near the world origin interpolated from corners 400 units away; rays
// reflected there must never hit the plane again (its other triangle included), and rays through it must
// never hit it twice.
TEST(Accel, OffsetOriginsOnHugeTiltedTrianglesAvoidSelfIntersection) {
  const Transform tilt =
      Transform::rotate(37, {1, 0, 0}) * Transform::rotate(23, {0, 0, 1}) * Transform::rotate(11, {0, 1, 0});
  for (float half : {400.0f, 4000.0f}) {
    Mesh plane;
    plane.positions = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
    plane.indices = {0, 1, 2, 0, 2, 3};
    plane.transform(tilt * Transform::translate({3.1f, -7.3f, 0.6f}));
    std::vector<Mesh> meshes{plane};
    const Accel accel(meshes);
    Random random;
    int self_hits = 0;
    for (int i = 0; i < 50000; ++i) {
      // Aim at points spread over the middle of the plane, from far away.
      const Vec3 target =
          tilt.point(Vec3((random.uniform() - 0.5f) * half, (random.uniform() - 0.5f) * half, 0));
      const Vec3 origin =
          target + tilt.vector(Vec3(0, 0, 1)) * (0.5f * half) + random.direction() * (0.1f * half);
      const Ray ray{origin, target - origin};
      const auto hit = accel.intersect(ray);
      if (!hit) continue;
      const SurfacePoint sp = surface_point(meshes, *hit, ray);
      const Vec3 n = dot(sp.ng, ray.dir) < 0 ? sp.ng : -sp.ng;
      const Vec3 d = normalize(ray.dir);
      const Vec3 mirrored = d - n * (2 * dot(d, n));
      if (accel.occluded(spawn_ray(sp, sp.ng, mirrored))) ++self_hits;
      if (accel.occluded(spawn_ray(sp, sp.ng, d))) ++self_hits;
    }
    EXPECT_EQ(self_hits, 0) << "half size " << half;
  }
}

// Long, thin quads (800 x 0.7, two triangles each, turned by a generic rotation, so that their rounded
// corners fold each quad by ~7e-5 radians along its diagonal): rays leaving either triangle near the
// diagonal never hit the other half, and a V of two such quads meeting at 90 degrees still catches the
// rays that leave one side toward the other a hair's breadth (1e-4) from the valley.
TEST(Accel, SpawnedRaysOnLongThinQuadsSeeNeitherTheFoldNorThroughTheValley) {
  const Transform turn = Transform::rotate(37, {1, 2, 3}) * Transform::translate({0.3f, -0.2f, 0.1f});
  const float half = 400.0f, width = 0.7f;
  // Side A rises from the valley line (along x) in +y, side B in -y, both at 45 degrees.
  const float c = width * std::sqrt(0.5f);
  Mesh v;
  v.positions = {{-half, 0, 0}, {half, 0, 0}, {half, c, c}, {-half, c, c}, {half, -c, c}, {-half, -c, c}};
  v.indices = {0, 1, 2, 0, 2, 3, 1, 0, 5, 1, 5, 4};  // A: triangles 0, 1; B: triangles 2, 3
  v.transform(turn);
  std::vector<Mesh> meshes{v};
  const Accel accel(meshes);
  Random random;
  int folds = 0, leaks = 0;
  for (int i = 0; i < 20000; ++i) {
    // A point on side A near its diagonal (from (-half, 0, 0) to (half, c, c)) or near the valley.
    const float along = (random.uniform() - 0.5f) * 1.6f * half;
    const bool near_valley = i % 2 == 1;
    const float across = near_valley ? 1e-4f : (along / half + 1) * 0.5f + (random.uniform() - 0.5f) * 2e-4f;
    const Vec3 local{along, across * c, across * c};
    const Vec3 target = turn.point(local);
    const Vec3 normal_a = normalize(turn.vector({0, -1, 1}));  // side A faces the valley's inside
    const Ray camera{target + normal_a * 2.0f + turn.vector({0.1f, 0, 0}),
                     -normal_a * 2.0f - turn.vector({0.1f, 0, 0})};
    const auto hit = accel.intersect(camera);
    if (!hit || hit->triangle > 1) continue;
    const SurfacePoint sp = surface_point(meshes, *hit, camera);
    if (near_valley) {
      // Toward side B, nearly parallel to A: B lies 1e-4 away across the valley, it must be found.
      const Vec3 toward_b = normalize(turn.vector({0.3f, -1, 0.02f}));
      const auto next = accel.intersect(spawn_ray(sp, sp.ng, toward_b));
      if (!next || next->triangle < 2) ++leaks;
    } else {
      // Leaving A at a low angle across its diagonal: nothing can be hit.
      const Vec3 grazing = normalize(turn.vector({0.2f, 1, 1.02f}));
      if (accel.occluded(spawn_ray(sp, sp.ng, grazing))) ++folds;
    }
  }
  EXPECT_EQ(folds, 0);
  EXPECT_EQ(leaks, 0);
}

TEST(Accel, SurfacePointInterpolatesColoursAndNormals) {
  Mesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.indices = {0, 1, 2};
  tri.normals = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  tri.colours = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<Mesh> meshes{tri};  // a copy: no spare capacity, Accel copies the positions
  const Accel accel(meshes);
  EXPECT_EQ(accel.copied_vertex_buffers(), 1u);
  const Ray ray{{0.25f, 0.5f, 1}, {0, 0, -1}};
  const auto hit = accel.intersect(ray);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->b1, 0.25f, 1e-6f);
  EXPECT_NEAR(hit->b2, 0.5f, 1e-6f);
  const SurfacePoint sp = surface_point(meshes, *hit, ray);
  ASSERT_TRUE(sp.has_colour);
  EXPECT_NEAR(sp.colour.x, 0.25f, 1e-6f);
  EXPECT_NEAR(sp.colour.y, 0.25f, 1e-6f);
  EXPECT_NEAR(sp.colour.z, 0.5f, 1e-6f);
  const Vec3 expected_ns = normalize(Vec3(0.25f, 0.5f, 1));
  EXPECT_NEAR(length(sp.ns - expected_ns), 0.0f, 1e-6f);
  EXPECT_FALSE(sp.has_uv);
  EXPECT_NEAR(dot(sp.dpdu, sp.ng), 0.0f, 1e-6f);
  EXPECT_NEAR(length(sp.dpdu), 1.0f, 1e-6f);
}

// Light sampling reads only the position and geometric normal of a point: triangle_position() and
// triangle_normal() must give exactly those of surface_point(), and a zero normal for a degenerate triangle.
TEST(Accel, TrianglePositionAndNormalAreThoseOfTheSurfacePoint) {
  Mesh tri;
  tri.positions = {{0.1f, -2, 3}, {1.7f, 0.3f, 2.5f}, {-0.4f, 1.2f, 3.9f}, {2, 2, 2}};
  tri.indices = {0, 1, 2, 3, 3, 3};
  tri.normals = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {0, 0, 1}};
  const Vec3 ng = triangle_normal(tri, 0);
  EXPECT_NEAR(length(ng), 1.0f, 1e-6f);
  for (float b1 : {0.0f, 0.2f, 0.7f})
    for (float b2 : {0.0f, 0.1f, 0.3f}) {
      const SurfacePoint sp = surface_point(tri, 0, b1, b2);
      const Vec3 p = triangle_position(tri, 0, b1, b2);
      EXPECT_EQ(p.x, sp.p.x);
      EXPECT_EQ(p.y, sp.p.y);
      EXPECT_EQ(p.z, sp.p.z);
      EXPECT_EQ(ng.x, sp.ng.x);
      EXPECT_EQ(ng.y, sp.ng.y);
      EXPECT_EQ(ng.z, sp.ng.z);
    }
  const Vec3 degenerate = triangle_normal(tri, 1);
  EXPECT_EQ(dot(degenerate, degenerate), 0.0f);
}

TEST(Accel, InvalidMeshesAreRejected) {
  Mesh bad;
  bad.name = "broken";
  bad.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.indices = {0, 1, 3};
  try {
    Accel accel(std::vector<Mesh>{bad});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken"), std::string::npos) << e.what();
  }
  bad.indices = {0, 1, 2};
  bad.positions[1].x = NAN;
  EXPECT_THROW(Accel(std::vector<Mesh>{bad}), InputError);
}

TEST(Accel, ConcurrentQueriesMatchSerialOnes) {
  std::vector<Mesh> meshes =
      mesh_list(make_sphere(1, 64), placed(make_plane({3, 3}), Transform::translate({0, 0, -1})));
  const Accel accel(meshes);
  Random random;
  std::vector<Ray> rays(20000);
  for (Ray& ray : rays) ray = {random.in_ball(2), random.direction()};
  auto trace = [&](std::vector<float>& ts) {
    for (size_t i = 0; i < rays.size(); ++i) {
      const auto hit = accel.intersect(rays[i]);
      ts[i] = hit ? hit->t : -1.0f;
    }
  };
  std::vector<float> serial(rays.size()), a(rays.size()), b(rays.size());
  trace(serial);
  std::thread ta(trace, std::ref(a)), tb(trace, std::ref(b));
  ta.join();
  tb.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);
}

// Build statistics on the scanned meshes (printed, never asserted: tests do not time).
void report_build(const char* name, const Mesh& mesh) {
  std::vector<Mesh> meshes;
  meshes.push_back(mesh);
  meshes[0].reserve_vertex_padding();
  const Accel accel(meshes);
  EXPECT_EQ(accel.copied_vertex_buffers(), 0u);
  const double triangles = static_cast<double>(mesh.triangle_count());
  // Incoherent rays through the bounding box, as a throughput sanity figure.
  Vec3 lo = mesh.positions[0], hi = lo;
  for (const Vec3& p : mesh.positions) lo = min(lo, p), hi = max(hi, p);
  const Vec3 centre = (lo + hi) * 0.5f;
  const float radius = 0.5f * length(hi - lo);
  Random random;
  std::vector<Ray> rays(200000);
  for (Ray& ray : rays) {
    const Vec3 origin = centre + random.direction() * (2 * radius);
    ray = {origin, centre + random.in_ball(0.5f * radius) - origin};
  }
  const int ray_count = static_cast<int>(rays.size());
  int hits = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const Ray& ray : rays) hits += accel.intersect(ray).has_value();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ info ] %s: %.0f triangles, BVH build %.3f s (%.2f M tri/s), memory %.1f MB = %.1f bytes/triangle "
      "(incl. %.1f of shared mesh arrays), %.2f Mrays/s incoherent (1 thread, %d%% hit)\n",
      name, triangles, accel.build_seconds(), triangles / accel.build_seconds() * 1e-6,
      accel.memory_bytes() * 1e-6, accel.memory_bytes() / triangles,
      (mesh.positions.size() * 12.0 + mesh.indices.size() * 4.0) / triangles, ray_count / seconds * 1e-6,
      100 * hits / ray_count);
  EXPECT_GT(hits, ray_count / 4);
}

TEST(Accel, ScannedMeshesBuildStatistics) {
  OCHRE_REQUIRE_SHARED();
  report_build("stanford-bunny.obj",
               import_mesh(test::shared_dir() / "assets/meshes/stanford-bunny.obj", Transform::identity()));
  report_build("gargo.ply",
               import_mesh(test::shared_dir() / "assets/meshes/3dhop/gargo.ply", Transform::identity()));
}

}  // namespace
}  // namespace ochre::accel_test
