#pragma once
// The throughput yardstick of ochre-bench (docs/tools.md): plain Embree on the same triangles the
// renderer traces, with random incoherent rays and nothing else (no shading, no sampling), so that
// renderer rays/s divided by these rays/s shows how much of the time is spent outside the BVH.
// No Embree types here: only ochre_renderer links Embree.

#include <cstdint>
#include <vector>

#include "renderer/geometry/mesh.h"

namespace ochre {

// The BVH options of a raw run. The renderer's Accel uses robust mode (watertight at shared edges) and
// high build quality; Embree's defaults are neither. ochre-bench measures both, so the ratio it reports
// is taken against the same BVH the renderer traces, and the cost of robust mode stays visible.
struct EmbreeSceneOptions {
  bool robust = true;
  bool high_quality = true;
};

struct RawEmbreeResult {
  uint64_t rays = 0;           // rtcIntersect1 queries traced
  uint64_t hits = 0;           // of which hit a triangle
  double seconds = 0.0;        // wall clock of the tracing (the BVH build excluded)
  double build_seconds = 0.0;  // rtcCommitScene
  int threads = 0;
  double rays_per_second() const { return seconds > 0 ? rays / seconds : 0.0; }
};

// Builds an Embree scene of `meshes` (world space) and traces, for at least `seconds` of wall clock
// on `threads` threads (0 = all cores), rays whose origins are uniform in the meshes' bounding box and
// whose directions are uniform on the sphere. Deterministic ray set for a given seed and batch count.
// Throws std::runtime_error on an Embree error or when there is no triangle.
RawEmbreeResult benchmark_raw_embree(const std::vector<Mesh>& meshes, int threads, double seconds,
                                     uint64_t seed, EmbreeSceneOptions options = {});

}  // namespace ochre
