#pragma once
// Accel: the Embree 3 acceleration structure over the scene's triangle meshes, plus the
// helpers that turn a hit into a shading point and spawn secondary rays without
// self-intersection (docs/architecture.md, "Spawning rays"). Embree stays private to accel.cpp.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "materials/core/vec3.h"
#include "renderer/geometry/mesh.h"
#include "renderer/geometry/ray.h"

namespace ochre {

struct Hit {
  float t = 0;
  uint32_t mesh = 0;      // index into the mesh list given to Accel (Embree's geomID)
  uint32_t triangle = 0;  // triangle index within that mesh (Embree's primID)
  float b1 = 0, b2 = 0;   // barycentrics of the triangle's vertices 1 and 2 (Embree's u, v)
  Vec3 ng;                // unnormalized geometric normal cross(p1 - p0, p2 - p0) (counter-clockwise winding)
};

// Bounding-volume hierarchy over all meshes: one Embree geometry per mesh, geomID = mesh index.
// Built once in the constructor (robust mode, high build quality, TBB-parallel), then const and
// safe to query from any number of threads.
class Accel {
 public:
  // The meshes must outlive the Accel and must not be modified while it exists: Embree reads
  // their position and index arrays in place. Embree loads each vertex with a 16-byte read, so
  // the last position needs 4 readable bytes after it: meshes whose `positions` vector has
  // spare capacity (all meshes made by this library: see Mesh::reserve_vertex_padding) are
  // shared without copying; the others have their positions copied into an Embree buffer.
  // Meshes are validated first (InputError naming the mesh on bad indices or non-finite data).
  explicit Accel(const std::vector<Mesh>& meshes);
  ~Accel();
  Accel(const Accel&) = delete;
  Accel& operator=(const Accel&) = delete;

  // Closest hit in (tmin, tmax), or nothing. Incoherent single-ray query (rtcIntersect1).
  // A ray spawned from a triangle (Ray::from_mesh, spawn_ray) never reports that triangle, and every hit
  // near its origin, where Embree's single-precision test can get the sign of t wrong, is checked against
  // the exact (double-precision) plane of the triangle hit.
  std::optional<Hit> intersect(const Ray& ray) const;
  // True when anything lies in (tmin, tmax) (rtcOccluded1, any-hit); spawned rays as for intersect.
  bool occluded(const Ray& ray) const;

  // Bytes allocated by Embree (BVH, copied vertex buffers; counted by the device memory
  // monitor) plus the shared mesh positions and indices.
  size_t memory_bytes() const;
  // Wall-clock time of the BVH build (rtcCommitScene).
  double build_seconds() const;
  // How many meshes needed their positions copied because they had no spare capacity.
  size_t copied_vertex_buffers() const;

  // Traversal timing, for ochre-bench: while on, every query adds its wall-clock duration to a per-thread
  // counter (two time-stamp-counter reads per query, ~10 ns each here). Switching it
  // on resets the counters. Off by default; then a query pays one predictable branch.
  void set_traversal_timing(bool on);
  // Seconds spent inside Embree queries, summed over all threads, since timing was switched on.
  double traversal_seconds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Everything the integrator needs about a hit point.
struct SurfacePoint {
  Vec3 p;        // position from the barycentrics (more precise than origin + t * dir)
  Vec3 p_error;  // conservative bound of |p - the exact point on the triangle| per component
  uint32_t mesh = Ray::kNoTriangle, triangle = Ray::kNoTriangle;  // the triangle p lies on
  Vec3 ng;               // unit geometric normal, cross(p1 - p0, p2 - p0) normalized (from the winding)
  Vec3 ns;               // unit shading normal: interpolated vertex normals, or ng for flat meshes
  Vec2 uv;               // interpolated texture coordinates, (0, 0) without UVs
  Vec3 colour{1, 1, 1};  // interpolated linear Rec.709 vertex colour, white without colours
  bool has_uv = false, has_colour = false;
  Vec3 dpdu;                // dp/du of the triangle's uv parametrization; without usable UVs, an arbitrary
                            // unit tangent perpendicular to ng
  float area_scale_uv = 0;  // world area per unit uv area of the triangle (0 without usable UVs)
};

// The point at barycentrics (b1, b2) of the triangle p0 p1 p2: SurfacePoint::p's arithmetic, shared with
// light sampling so that both give the same bits. The sum is taken in double precision and rounded once, so
// the point is within half a unit in the last place of its coordinates of the triangle's plane, however far
// the corners are: in single precision a point in the middle of a triangle 800 long is only as precise as
// its corners' coordinates (the products cancel), and the spawned ray's offset would grow with them.
inline Vec3 barycentric_point(const Vec3& p0, const Vec3& p1, const Vec3& p2, float b1, float b2) {
  const double w1 = b1, w2 = b2, w0 = 1.0 - w1 - w2;
  return {static_cast<float>(w0 * p0.x + w1 * p1.x + w2 * p2.x),
          static_cast<float>(w0 * p0.y + w1 * p1.y + w2 * p2.y),
          static_cast<float>(w0 * p0.z + w1 * p1.z + w2 * p2.z)};
}
// Light sampling needs only a point's position and the triangle's unit geometric normal (0 for a degenerate
// triangle): exactly the p and ng of surface_point(), without its error bound, normal and tangent work. The
// normal does not depend on the point, so a light computes it once per triangle.
inline Vec3 triangle_position(const Mesh& mesh, uint32_t triangle, float b1, float b2) {
  const uint32_t* corner = &mesh.indices[3 * size_t(triangle)];
  return barycentric_point(mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]],
                           b1, b2);
}
Vec3 triangle_normal(const Mesh& mesh, uint32_t triangle);

// Shading point of a hit returned by Accel::intersect on the same meshes. The ray is only used
// as a fallback for p when the triangle is degenerate.
// The point at barycentrics (b1, b2) of a triangle; ng is 0 for a degenerate triangle.
SurfacePoint surface_point(const Mesh& mesh, uint32_t triangle, float b1, float b2);
SurfacePoint surface_point(const std::vector<Mesh>& meshes, const Hit& hit, const Ray& ray);

// Origin for a ray leaving the surface point p (with the error bound p_error of SurfacePoint, geometric
// normal ng of any length) in direction dir: p pushed off the surface along ng, on the side dir points
// to, by the projection of the error bound on the normal, then rounded away from p (pbrt-v4,
// OffsetRayOrigin; Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., sec. 6.8.6). The
// bound grows with the triangle's corners, not with |p|: a point near the origin of a huge tilted
// triangle is as uncertain as its corners. Use tmin = 0 with the returned origin.
Vec3 offset_ray_origin(const Vec3& p, const Vec3& p_error, const Vec3& ng, const Vec3& dir);

// The ray leaving the surface point `sp` in direction `dir` (ng: the geometric normal, any orientation):
// from offset_ray_origin, naming the triangle it leaves so that Accel never reports that triangle and
// checks hits near the origin exactly. The offset is the interpolation error bound alone, however long
// and thin the triangle: an image does not depend on how a surface is cut into triangles.
Ray spawn_ray(const SurfacePoint& sp, const Vec3& ng, const Vec3& dir, float tmax = INFINITY);

}  // namespace ochre
