#include "renderer/geometry/accel.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>

#include "materials/core/frame.h"

namespace ochre {

namespace {

// The first Embree error reported by the device callback; checked after each API phase, so
// errors surface as exceptions in the calling thread instead of unwinding through Embree.
struct EmbreeErrors {
  std::mutex mutex;
  std::string first;

  static void record(void* user, RTCError code, const char* message) {
    auto* self = static_cast<EmbreeErrors*>(user);
    std::lock_guard lock(self->mutex);
    if (self->first.empty())
      self->first = fmt::format("Embree error {}: {}", static_cast<int>(code), message ? message : "");
  }
  void throw_if_any(const char* phase) {
    std::lock_guard lock(mutex);
    if (!first.empty()) throw std::runtime_error(fmt::format("Accel ({}): {}", phase, first));
  }
};

// A cheap monotonic tick counter: the time-stamp counter on x86 (constant rate on every CPU since ~2008;
// a clock_gettime through a virtual machine's clock can cost more than the query it would time), else
// steady_clock nanoseconds. Converted to seconds against steady_clock over the whole timed interval.
int64_t ticks() {
#if defined(__x86_64__) || defined(__i386__)
  return static_cast<int64_t>(__rdtsc());
#else
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
#endif
}

// Sums Embree's allocations and frees (the BVH, copied buffers, build scratch already freed).
bool count_memory(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<int64_t>*>(user)->fetch_add(bytes, std::memory_order_relaxed);
  return true;
}

// The intersection context of a spawned ray: Embree hands it back to the filter (it starts with the
// RTCIntersectContext), with the triangle the ray leaves and the meshes to read corners from.
struct SpawnContext {
  RTCIntersectContext embree;
  const std::vector<Mesh>* meshes;
  const float* longest_edge;  // per mesh: the longest triangle edge (largest component)
  uint32_t from_mesh, from_triangle;
};

float max_component_magnitude(float x, float y, float z) {
  return std::max(std::fabs(x), std::max(std::fabs(y), std::fabs(z)));
}

// The largest coordinate difference between two corners of one triangle of the mesh.
float longest_edge(const Mesh& mesh) {
  float longest = 0.0f;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vec3 &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
               &c = mesh.positions[mesh.indices[t + 2]];
    for (const Vec3 e : {b - a, c - a, c - b})
      longest = std::max(longest, max_component_magnitude(e.x, e.y, e.z));
  }
  return longest;
}

// Embree computes a triangle's corners relative to the ray origin in single precision, so where the ray
// crosses the triangle's plane is off by up to a few epsilons times the distance from the origin to the far
// corner (measured: 3.6 eps per unit), and near the plane the side can be wrong: a ray leaving a long, thin
// triangle finds it again, or a neighbour, at t ~ 1e-9, and a ray leaving at a grazing angle finds the
// neighbour's plane farther on. Hits whose origin lies within 128 eps per unit of that distance of the
// triangle's plane are checked exactly.
constexpr float kCheckEpsilon = 64.0f * 0x1p-24f;

// Where the plane of the triangle v0 v1 v2 lies from o, in double precision: the corners, origin and
// direction are floats, so the differences and products are exact or within 1e-16 relative, far below the
// single-precision offsets a spawned origin has.
struct ExactPlane {
  double distance;  // from o to the plane, perpendicular (NaN for a degenerate triangle)
  double t;         // along d, in units of |d| (NaN or infinite for a ray parallel to the plane)
};
ExactPlane exact_plane(const Vec3& o, const Vec3& d, const Vec3& v0, const Vec3& v1, const Vec3& v2) {
  const double e1[3] = {double(v1.x) - v0.x, double(v1.y) - v0.y, double(v1.z) - v0.z};
  const double e2[3] = {double(v2.x) - v0.x, double(v2.y) - v0.y, double(v2.z) - v0.z};
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
  const double to_corner[3] = {double(v0.x) - o.x, double(v0.y) - o.y, double(v0.z) - o.z};
  const double numerator = n[0] * to_corner[0] + n[1] * to_corner[1] + n[2] * to_corner[2];
  const double denominator = n[0] * d.x + n[1] * d.y + n[2] * d.z;
  return {numerator / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), numerator / denominator};
}

// A triangle nearly in the plane of the one a spawned ray leaves, and within a few units in the last place of
// its corners' coordinates of the ray's origin, is the same surface: the corners of one flat polygon,
// rounded to single precision (a quad turned by a transform, a scan's facets), do not lie in one plane, and
// the two triangles of a quad 800 long and 0.7 wide meet at a fold of 7e-5 radians that would catch rays
// leaving the polygon near its diagonal. Triangles at a real angle (a groove's other facet) are judged by
// the exact test alone, so no band along a concave edge loses its hits.
constexpr double kSameSurfaceUlps = 8.0 * 0x1p-24;
constexpr double kSameSurfaceSine = 1e-3;  // planes closer than this angle (radians) are one surface

// The unit normal of a triangle in double precision (zero for a degenerate one).
std::array<double, 3> exact_unit_normal(const Vec3& v0, const Vec3& v1, const Vec3& v2) {
  const double e1[3] = {double(v1.x) - v0.x, double(v1.y) - v0.y, double(v1.z) - v0.z};
  const double e2[3] = {double(v2.x) - v0.x, double(v2.y) - v0.y, double(v2.z) - v0.z};
  std::array<double, 3> n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > 0.0)
    for (double& c : n) c /= length;
  return n;
}

// Whether the triangles of unit normals a and b lie in nearly the same plane (either orientation).
bool nearly_parallel(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return c[0] * c[0] + c[1] * c[1] + c[2] * c[2] < kSameSurfaceSine * kSameSurfaceSine;
}

// The context filter of spawned rays (Accel::intersect, Accel::occluded): rejects the triangle the ray
// leaves (a flat triangle cannot be hit again by a ray leaving it) and every hit near the origin that the
// exact test puts behind it or within the rounding of the corners from it (kSameSurfaceUlps).
void verify_spawned_hit(const RTCFilterFunctionNArguments* args) {
  const auto* spawn = reinterpret_cast<const SpawnContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned mesh_id = RTCHitN_geomID(args->hit, args->N, i);
    const unsigned triangle = RTCHitN_primID(args->hit, args->N, i);
    if (mesh_id == spawn->from_mesh && triangle == spawn->from_triangle) {
      args->valid[i] = 0;
      continue;
    }
    const Vec3 d{RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                 RTCRayN_dir_z(args->ray, args->N, i)};
    const Vec3 ng{RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                  RTCHitN_Ng_z(args->hit, args->N, i)};
    const float t = RTCRayN_tfar(args->ray, args->N, i);  // the candidate hit's distance
    // How far the origin is from the candidate's plane (estimated in single precision), against Embree's
    // error there, which grows with the distance from the origin to the triangle's corners: no farther than
    // the hit plus the mesh's longest edge. Clear of it, the hit stands (most hits: no corners read).
    // height = t |ng . d| / |ng| against the bound, squared: no root or division on this path.
    const float bound =
        2.0f * kCheckEpsilon * (t * max_component_magnitude(d.x, d.y, d.z) + spawn->longest_edge[mesh_id]);
    const float along_normal = t * dot(ng, d);
    if (along_normal * along_normal > bound * bound * dot(ng, ng)) continue;
    const Vec3 o{RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                 RTCRayN_org_z(args->ray, args->N, i)};
    const Mesh& mesh = (*spawn->meshes)[mesh_id];
    const uint32_t* corner = &mesh.indices[3 * size_t(triangle)];
    const Vec3 &v0 = mesh.positions[corner[0]], &v1 = mesh.positions[corner[1]],
               &v2 = mesh.positions[corner[2]];
    const ExactPlane plane = exact_plane(o, d, v0, v1, v2);
    if (!(plane.t > 0.0)) {
      args->valid[i] = 0;
      continue;
    }
    float magnitude = 0.0f;
    for (const Vec3* v : {&v0, &v1, &v2})
      magnitude = std::max(magnitude, max_component_magnitude(v->x, v->y, v->z));
    if (std::fabs(plane.distance) > kSameSurfaceUlps * magnitude) continue;
    const Mesh& from = (*spawn->meshes)[spawn->from_mesh];
    const uint32_t* from_corner = &from.indices[3 * size_t(spawn->from_triangle)];
    if (nearly_parallel(exact_unit_normal(v0, v1, v2),
                        exact_unit_normal(from.positions[from_corner[0]], from.positions[from_corner[1]],
                                          from.positions[from_corner[2]])))
      args->valid[i] = 0;
  }
}

// The context of a query: a spawned ray gets the filter, a camera ray Embree's default context.
SpawnContext query_context(const Ray& ray, const std::vector<Mesh>* meshes, const float* longest_edge) {
  SpawnContext context{};
  rtcInitIntersectContext(&context.embree);
  context.meshes = meshes;
  context.longest_edge = longest_edge;
  context.from_mesh = ray.from_mesh;
  context.from_triangle = ray.from_triangle;
  if (ray.from_mesh != Ray::kNoTriangle) context.embree.filter = &verify_spawned_hit;
  return context;
}
}  // namespace

struct Accel::Impl {
  const std::vector<Mesh>* meshes = nullptr;  // the vertices the exact checks of spawned rays read
  std::vector<float> longest_edge;            // per mesh, for the checks (verify_spawned_hit)
  EmbreeErrors errors;
  std::atomic<int64_t> embree_bytes{0};
  size_t shared_bytes = 0;
  size_t copied_buffers = 0;
  double build_seconds = 0;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  // Traversal timing (set_traversal_timing): per-thread tick sums and the interval's start.
  std::atomic<bool> timing{false};
  mutable tbb::enumerable_thread_specific<int64_t> traversal_ticks{0};
  int64_t timing_start_ticks = 0;
  std::chrono::steady_clock::time_point timing_start;

  // Runs query() and, when timing is on, adds its duration to this thread's tick sum.
  template <typename Query>
  void traced(Query&& query) const;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void add_mesh(const Mesh& mesh, unsigned id) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t vertex_count = mesh.positions.size();
    if (mesh.positions.capacity() > vertex_count) {
      // The spare element makes the 16-byte load of the last vertex read allocated memory.
      rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                 mesh.positions.data(), 0, sizeof(Vec3), vertex_count);
      shared_bytes += vertex_count * sizeof(Vec3);
    } else {
      // Embree pads buffers it allocates itself.
      auto* copy = static_cast<Vec3*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT3, sizeof(Vec3), vertex_count));
      if (copy) std::copy(mesh.positions.begin(), mesh.positions.end(), copy);
      ++copied_buffers;
    }
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                               3 * sizeof(uint32_t), mesh.triangle_count());
    shared_bytes += mesh.indices.size() * sizeof(uint32_t);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, id);
    rtcReleaseGeometry(geometry);
  }
};

template <typename Query>
void Accel::Impl::traced(Query&& query) const {
  if (!timing.load(std::memory_order_relaxed)) {
    query();
    return;
  }
  const int64_t start = ticks();
  query();
  traversal_ticks.local() += ticks() - start;
}

Accel::Accel(const std::vector<Mesh>& meshes) : impl_(std::make_unique<Impl>()) {
  for (size_t i = 0; i < meshes.size(); ++i) {
    meshes[i].validate(fmt::format("mesh {} '{}'", i, meshes[i].name));
  }
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device)
    throw std::runtime_error(fmt::format("Accel: cannot create the Embree device (error {})",
                                         static_cast<int>(rtcGetDeviceError(nullptr))));
  rtcSetDeviceErrorFunction(impl_->device, &EmbreeErrors::record, &impl_->errors);
  rtcSetDeviceMemoryMonitorFunction(impl_->device, &count_memory, &impl_->embree_bytes);

  impl_->meshes = &meshes;
  impl_->longest_edge.reserve(meshes.size());
  for (const Mesh& mesh : meshes) impl_->longest_edge.push_back(longest_edge(mesh));
  impl_->scene = rtcNewScene(impl_->device);
  // Robust mode keeps the watertight triangle test exact at shared edges (no rays slip through). The context
  // filter checks the hits of spawned rays (verify_spawned_hit); camera rays carry no filter.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  for (size_t i = 0; i < meshes.size(); ++i) {
    // Empty meshes get no geometry; the IDs of the others still equal their mesh index.
    if (meshes[i].triangle_count() > 0) impl_->add_mesh(meshes[i], static_cast<unsigned>(i));
  }
  impl_->errors.throw_if_any("geometry set-up");

  const auto start = std::chrono::steady_clock::now();
  rtcCommitScene(impl_->scene);
  impl_->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  impl_->errors.throw_if_any("BVH build");
}

Accel::~Accel() = default;

void Accel::set_traversal_timing(bool on) {
  if (on) {
    for (int64_t& n : impl_->traversal_ticks) n = 0;
    impl_->timing_start_ticks = ticks();
    impl_->timing_start = std::chrono::steady_clock::now();
  }
  impl_->timing.store(on, std::memory_order_relaxed);
}

double Accel::traversal_seconds() const {
  int64_t total = 0;
  for (const int64_t n : impl_->traversal_ticks) total += n;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - impl_->timing_start).count();
  const double elapsed_ticks = static_cast<double>(ticks() - impl_->timing_start_ticks);
  return elapsed_ticks > 0.0 ? static_cast<double>(total) * seconds / elapsed_ticks : 0.0;
}

std::optional<Hit> Accel::intersect(const Ray& ray) const {
  if (!(ray.tmax > ray.tmin)) return std::nullopt;
  SpawnContext context = query_context(ray, impl_->meshes, impl_->longest_edge.data());
  RTCRayHit query{};
  query.ray.org_x = ray.origin.x;
  query.ray.org_y = ray.origin.y;
  query.ray.org_z = ray.origin.z;
  query.ray.dir_x = ray.dir.x;
  query.ray.dir_y = ray.dir.y;
  query.ray.dir_z = ray.dir.z;
  query.ray.tnear = ray.tmin;
  query.ray.tfar = ray.tmax;
  query.ray.mask = ~0u;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  impl_->traced([&] { rtcIntersect1(impl_->scene, &context.embree, &query); });
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  // Embree's Ng for triangles is cross(v1 - v0, v2 - v0) (checked by the Accel tests).
  return Hit{query.ray.tfar, query.hit.geomID, query.hit.primID,
             query.hit.u,    query.hit.v,      Vec3{query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z}};
}

bool Accel::occluded(const Ray& ray) const {
  if (!(ray.tmax > ray.tmin)) return false;
  SpawnContext context = query_context(ray, impl_->meshes, impl_->longest_edge.data());
  RTCRay query{};
  query.org_x = ray.origin.x;
  query.org_y = ray.origin.y;
  query.org_z = ray.origin.z;
  query.dir_x = ray.dir.x;
  query.dir_y = ray.dir.y;
  query.dir_z = ray.dir.z;
  query.tnear = ray.tmin;
  query.tfar = ray.tmax;
  query.mask = ~0u;
  impl_->traced([&] { rtcOccluded1(impl_->scene, &context.embree, &query); });
  return query.tfar == -INFINITY;  // Embree marks an occluded ray with tfar = -inf
}

size_t Accel::memory_bytes() const {
  return static_cast<size_t>(std::max<int64_t>(0, impl_->embree_bytes.load())) + impl_->shared_bytes;
}

double Accel::build_seconds() const {
  return impl_->build_seconds;
}

size_t Accel::copied_vertex_buffers() const {
  return impl_->copied_buffers;
}

// ------------------------------------------------------------------------------- surface points

namespace {

template <typename T>
T interpolate(const std::vector<T>& values, const uint32_t* corner, float b0, float b1, float b2) {
  return values[corner[0]] * b0 + values[corner[1]] * b1 + values[corner[2]] * b2;
}

Vec2 interpolate(const std::vector<Vec2>& uvs, const uint32_t* corner, float b0, float b1, float b2) {
  const Vec2 &a = uvs[corner[0]], &b = uvs[corner[1]], &c = uvs[corner[2]];
  return {a.x * b0 + b.x * b1 + c.x * b2, a.y * b0 + b.y * b1 + c.y * b2};
}

bool usable_unit(const Vec3& v) {
  return dot(v, v) > 0.0f && std::isfinite(dot(v, v));
}

// dp/du and the world-per-uv area ratio from the triangle's uv parametrization (pbrt-v3,
// Pharr et al. 2016, sec. 3.6.2). Returns false when the uv triangle is degenerate.
bool uv_derivatives(const Vec3 p[3], const Vec2 uv[3], float world_double_area, Vec3& dpdu,
                    float& area_scale) {
  const Vec2 duv02{uv[0].x - uv[2].x, uv[0].y - uv[2].y}, duv12{uv[1].x - uv[2].x, uv[1].y - uv[2].y};
  const Vec3 dp02 = p[0] - p[2], dp12 = p[1] - p[2];
  const float determinant = duv02.x * duv12.y - duv02.y * duv12.x;
  if (!(std::fabs(determinant) > 1e-12f)) return false;
  dpdu = (dp02 * duv12.y - dp12 * duv02.y) / determinant;
  area_scale = world_double_area / std::fabs(determinant);
  return usable_unit(dpdu) && std::isfinite(area_scale);
}

}  // namespace

namespace {

// The error bound of a point from barycentric_point: the rounding of the double sum to single precision
// (half a unit in the last place, at most 2^-24 |p|) and the double arithmetic itself (a few 2^-53 times the
// sum of |b_i p_i|, bounded generously by 2^-44). Embree's own error near a spawned ray's origin is handled
// by the exact checks of verify_spawned_hit, not by a larger offset.
constexpr float kRoundingToFloat = 0x1p-24f;
constexpr float kDoubleSum = 0x1p-44f;
// The bound of a point computed in single precision as origin + t dir (degenerate triangles): pbrt-v4's
// gamma(7) (Eq 6.28).
constexpr float kGamma7 = 7.0f * 0x1p-24f / (1.0f - 7.0f * 0x1p-24f);

// Position, error bound, unit geometric normal (0 for a degenerate triangle) and doubled area at barycentrics
// (b1, b2) of a triangle.
struct TrianglePoint {
  Vec3 p;
  Vec3 p_error;  // conservative absolute error bound of p per component (offset_ray_origin)
  Vec3 ng;
  float double_area = 0;  // |cross(p1 - p0, p2 - p0)|
};

// Position, error bound, normal and doubled area from the triangle's corners (shared by the two functions
// below, which load the corners once).
TrianglePoint point_on(const Vec3 p[3], float b1, float b2) {
  TrianglePoint t;
  const float b0 = 1.0f - b1 - b2;
  t.p = barycentric_point(p[0], p[1], p[2], b1, b2);
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  t.p_error = abs(t.p) * kRoundingToFloat + (abs(p[0] * b0) + abs(p[1] * b1) + abs(p[2] * b2)) * kDoubleSum;
  const Vec3 n = cross(e1, e2);
  t.double_area = length(n);
  t.ng = t.double_area > 0.0f && std::isfinite(t.double_area) ? n / t.double_area : Vec3(0, 0, 0);
  return t;
}

}  // namespace

Vec3 triangle_normal(const Mesh& mesh, uint32_t triangle) {
  const uint32_t* corner = &mesh.indices[3 * size_t(triangle)];
  const Vec3 p[3] = {mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]};
  return point_on(p, 0.0f, 0.0f).ng;
}

SurfacePoint surface_point(const Mesh& mesh, uint32_t triangle, float b1, float b2) {
  const uint32_t* corner = &mesh.indices[3 * size_t(triangle)];
  const Vec3 p[3] = {mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]};
  const float b0 = 1.0f - b1 - b2;

  SurfacePoint sp;
  const TrianglePoint t = point_on(p, b1, b2);
  sp.triangle = triangle;
  sp.p = t.p;
  sp.p_error = t.p_error;
  sp.ng = t.ng;
  const float double_area = t.double_area;
  sp.ns = sp.ng;
  if (!mesh.normals.empty()) {
    const Vec3 ns = interpolate(mesh.normals, corner, b0, b1, b2);
    if (usable_unit(ns)) sp.ns = normalize(ns);
  }
  if (!mesh.colours.empty()) {
    sp.colour = interpolate(mesh.colours, corner, b0, b1, b2);
    sp.has_colour = true;
  }
  bool have_derivatives = false;
  if (!mesh.uvs.empty()) {
    sp.uv = interpolate(mesh.uvs, corner, b0, b1, b2);
    sp.has_uv = true;
    const Vec2 uv[3] = {mesh.uvs[corner[0]], mesh.uvs[corner[1]], mesh.uvs[corner[2]]};
    have_derivatives = uv_derivatives(p, uv, double_area, sp.dpdu, sp.area_scale_uv);
  }
  if (!have_derivatives) {
    sp.dpdu = usable_unit(sp.ng) ? Frame::from_normal(sp.ng).s : Vec3(1, 0, 0);
    sp.area_scale_uv = 0.0f;
  }
  return sp;
}

SurfacePoint surface_point(const std::vector<Mesh>& meshes, const Hit& hit, const Ray& ray) {
  SurfacePoint sp = surface_point(meshes[hit.mesh], hit.triangle, hit.b1, hit.b2);
  sp.mesh = hit.mesh;
  if (!usable_unit(sp.ng)) {  // degenerate triangle: face the ray
    sp.ng = usable_unit(hit.ng) ? normalize(hit.ng) : normalize(-ray.dir);
    sp.ns = sp.ng;
    sp.p = ray.origin + ray.dir * hit.t;
    sp.p_error = (abs(ray.origin) + abs(ray.dir * hit.t)) * kGamma7;
    sp.dpdu = Frame::from_normal(sp.ng).s;
  }
  return sp;
}

Ray spawn_ray(const SurfacePoint& sp, const Vec3& ng, const Vec3& dir, float tmax) {
  Ray ray{offset_ray_origin(sp.p, sp.p_error, ng, dir), dir, 0.0f, tmax};
  if (sp.mesh != Ray::kNoTriangle) {
    ray.from_mesh = sp.mesh;
    ray.from_triangle = sp.triangle;
  }
  return ray;
}

Vec3 offset_ray_origin(const Vec3& p, const Vec3& p_error, const Vec3& ng, const Vec3& dir) {
  Vec3 n = normalize(ng);
  if (dot(n, dir) < 0.0f) n = -n;
  // An error bound of 0 (a triangle in a coordinate plane such as z = 0, where p is exact) still needs the
  // origin strictly off the plane: Embree reports hits at t = 0, unlike pbrt's conservative test.
  constexpr float kMinOffset = 1e-20f;
  const Vec3 offset = n * std::max(dot(abs(n), p_error), kMinOffset);
  Vec3 out = p + offset;
  // Round away from p (the sum may have rounded back towards it): one step of the bit pattern, the
  // library's nextafter without its call (out is finite).
  for (int axis = 0; axis < 3; ++axis) {
    if (offset[axis] == 0.0f) continue;
    const bool up = offset[axis] > 0.0f;
    float v = out[axis];
    if (v == 0.0f) v = up ? 0.0f : -0.0f;  // the step from +-0 goes to the smallest float on its side
    const int32_t bits = std::bit_cast<int32_t>(v);
    out[axis] = std::bit_cast<float>(bits + (!std::signbit(v) == up ? 1 : -1));
  }
  return out;
}

}  // namespace ochre
