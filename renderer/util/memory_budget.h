#pragma once
// Memory estimates, checked before large allocations: the film with every layer and output buffer, a
// subdivided or tessellated mesh, a decoded image. A request the machine cannot hold then fails at once
// with exit code 2 and the estimate ("film 65536x65536 (XYZ) needs 416 GiB; this machine has 23 GiB (use
// --memory-limit to change the limit)") instead of std::bad_alloc or the kernel's OOM killer hours later
// (docs/cli.md, "Memory").

#include <cstdint>
#include <optional>
#include <string>

namespace ochre {

// Physical memory of the machine (sysconf, else /proc/meminfo MemTotal), or the memory.max of the
// process's cgroup (v2) when that is lower.
std::uint64_t machine_memory_bytes();

// The limit estimates are compared with: `bytes` (--memory-limit), or machine_memory_bytes() when
// nothing is set. Process-wide.
void set_memory_limit(std::optional<std::uint64_t> bytes);
std::uint64_t memory_limit();

// Throws InputError "<what> needs <estimate>; this machine has <limit> (use --memory-limit to change the
// limit)", or "...; the memory limit (--memory-limit) is <limit>", when `bytes` exceeds the limit.
// Estimates are doubles: a product of counts cannot overflow.
void check_memory_estimate(double bytes, const std::string& what);

// A mesh of `triangles` triangles at `bytes_per_triangle` (below): check_memory_estimate(), and more than
// 2^31 triangles refused whatever the limit, since the renderer's indices are 32-bit (a mesh has no more
// vertices than twice its triangles). Throws InputError starting with `what`.
void check_triangle_estimate(double triangles, double bytes_per_triangle, const std::string& what);

// Peak bytes per triangle while a mesh is built and its BVH (renderer/geometry/accel.h) with it, measured
// with /usr/bin/time (maximum resident set): 122 for a tessellated sphere of 16.8 M triangles (positions,
// normals, uvs, indices, Embree's build), 270 for a Catmull-Clark surface of 2 M triangles (OpenSubdiv's
// refiner and primvars besides); rounded up.
inline constexpr double kTessellatedTriangleBytes = 150;
inline constexpr double kSubdividedTriangleBytes = 300;

// "412 GiB" for an estimate (saturates above 2^64 bytes).
std::string format_estimate(double bytes);

}  // namespace ochre
