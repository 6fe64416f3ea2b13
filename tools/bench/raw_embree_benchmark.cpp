#include "tools/bench/raw_embree_benchmark.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ochre {

namespace {

// Rays per task: large enough that scheduling costs nothing, small enough to balance 2..64 threads.
constexpr uint32_t kRaysPerBatch = 4096;
// Batches handed to the pool between two looks at the clock.
constexpr uint32_t kBatchesPerRound = 256;

using Bounds = Mesh::Bounds;

Bounds mesh_bounds(const std::vector<Mesh>& meshes) {
  Bounds b;
  for (const Mesh& mesh : meshes) b.include(mesh.bounds());
  return b;
}

// SplitMix64 (Steele, Lea, Flood 2014): a counter-based stream, one per batch, so the rays do not
// depend on which thread traces which batch.
struct SplitMix64 {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float uniform() { return static_cast<float>(next() >> 40) * 0x1.0p-24f; }  // [0, 1)
};

struct EmbreeHandles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~EmbreeHandles() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

void throw_on_error(RTCDevice device, const char* phase) {
  const RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE)
    throw std::runtime_error(
        fmt::format("raw Embree benchmark ({}): Embree error {}", phase, static_cast<int>(code)));
}

// Copies every mesh into Embree-owned buffers (Embree pads them for its 16-byte vertex loads).
void attach_meshes(RTCDevice device, RTCScene scene, const std::vector<Mesh>& meshes) {
  for (const Mesh& mesh : meshes) {
    if (mesh.triangle_count() == 0) continue;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<Vec3*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3), mesh.positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangle_count()));
    if (vertices) std::copy(mesh.positions.begin(), mesh.positions.end(), vertices);
    if (indices) std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
  }
}

// Traces one batch of random rays; returns the number of hits.
uint64_t trace_batch(RTCScene scene, const Bounds& b, uint64_t seed, uint64_t batch) {
  SplitMix64 rng{seed ^ (batch * 0xD1B54A32D192ED03ull)};
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  uint64_t hits = 0;
  for (uint32_t i = 0; i < kRaysPerBatch; ++i) {
    RTCRayHit rh{};
    rh.ray.org_x = b.lo.x + rng.uniform() * (b.hi.x - b.lo.x);
    rh.ray.org_y = b.lo.y + rng.uniform() * (b.hi.y - b.lo.y);
    rh.ray.org_z = b.lo.z + rng.uniform() * (b.hi.z - b.lo.z);
    // Uniform direction on the sphere: z uniform in [-1, 1], azimuth uniform (Archimedes).
    const float z = 1.0f - 2.0f * rng.uniform();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * std::numbers::pi_v<float> * rng.uniform();
    rh.ray.dir_x = r * std::cos(phi);
    rh.ray.dir_y = r * std::sin(phi);
    rh.ray.dir_z = z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }
  return hits;
}

}  // namespace

RawEmbreeResult benchmark_raw_embree(const std::vector<Mesh>& meshes, int threads, double seconds,
                                     uint64_t seed, EmbreeSceneOptions options) {
  size_t triangles = 0;
  for (const Mesh& mesh : meshes) triangles += mesh.triangle_count();
  if (triangles == 0) throw std::runtime_error("raw Embree benchmark: the scene has no triangle");

  RawEmbreeResult result;
  result.threads = threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(result.threads);

  EmbreeHandles embree;
  const std::string config = fmt::format("threads={}", result.threads);
  embree.device = rtcNewDevice(config.c_str());
  if (!embree.device) throw std::runtime_error("raw Embree benchmark: rtcNewDevice failed");
  embree.scene = rtcNewScene(embree.device);
  if (options.robust) rtcSetSceneFlags(embree.scene, RTC_SCENE_FLAG_ROBUST);
  if (options.high_quality) rtcSetSceneBuildQuality(embree.scene, RTC_BUILD_QUALITY_HIGH);
  attach_meshes(embree.device, embree.scene, meshes);
  const auto build_start = std::chrono::steady_clock::now();
  arena.execute([&] { rtcCommitScene(embree.scene); });
  result.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
  throw_on_error(embree.device, "build");

  const Bounds bounds = mesh_bounds(meshes);
  std::atomic<uint64_t> hits{0};
  uint64_t batches = 0;
  const auto start = std::chrono::steady_clock::now();
  do {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<uint64_t>(batches, batches + kBatchesPerRound),
                        [&](const tbb::blocked_range<uint64_t>& range) {
                          uint64_t local = 0;
                          for (uint64_t batch = range.begin(); batch != range.end(); ++batch)
                            local += trace_batch(embree.scene, bounds, seed, batch);
                          hits.fetch_add(local, std::memory_order_relaxed);
                        });
    });
    batches += kBatchesPerRound;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (result.seconds < seconds);
  throw_on_error(embree.device, "trace");

  result.rays = batches * kRaysPerBatch;
  result.hits = hits.load();
  return result;
}

}  // namespace ochre
