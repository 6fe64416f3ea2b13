#include "renderer/util/memory_budget.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <mutex>

#include "spectra/byte_size.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

std::mutex limit_mutex;
std::optional<std::uint64_t> explicit_limit;  // guarded by limit_mutex

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page_size = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0)
    return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  while (meminfo >> key >> kib) {
    if (key == "MemTotal:") return kib * kKiB;
    meminfo.ignore(256, '\n');
  }
  return 0;
}

// memory.max of the cgroup (v2) this process runs in; nothing when unlimited or unknown.
std::optional<std::uint64_t> cgroup_memory_max() {
  std::ifstream cgroup("/proc/self/cgroup");
  std::string line;
  while (std::getline(cgroup, line)) {
    if (line.rfind("0::", 0) != 0) continue;  // the v2 hierarchy
    std::ifstream max_file("/sys/fs/cgroup" + line.substr(3) + "/memory.max");
    std::uint64_t bytes = 0;
    if (max_file >> bytes && bytes > 0) return bytes;  // "max" (unlimited) fails to parse
  }
  return std::nullopt;
}

}  // namespace

std::uint64_t machine_memory_bytes() {
  static const std::uint64_t bytes = [] {
    std::uint64_t physical = physical_memory_bytes();
    const std::optional<std::uint64_t> cgroup = cgroup_memory_max();
    if (cgroup && (physical == 0 || *cgroup < physical)) physical = *cgroup;
    return physical;
  }();
  return bytes;
}

void set_memory_limit(std::optional<std::uint64_t> bytes) {
  std::lock_guard lock(limit_mutex);
  explicit_limit = bytes;
}

std::uint64_t memory_limit() {
  std::lock_guard lock(limit_mutex);
  return explicit_limit ? *explicit_limit : machine_memory_bytes();
}

std::string format_estimate(double bytes) {
  constexpr double kMax = 18446744073709549568.0;  // the largest double below 2^64
  return format_bytes(bytes >= kMax ? UINT64_MAX : static_cast<std::uint64_t>(std::max(bytes, 0.0)));
}

void check_memory_estimate(double bytes, const std::string& what) {
  std::optional<std::uint64_t> given;
  {
    std::lock_guard lock(limit_mutex);
    given = explicit_limit;
  }
  const std::uint64_t limit = given ? *given : machine_memory_bytes();
  if (limit == 0 || bytes <= static_cast<double>(limit)) return;  // 0: the machine's memory is unknown
  if (given)
    throw InputError(fmt::format("{} needs {}; the memory limit (--memory-limit) is {}", what,
                                 format_estimate(bytes), format_bytes(limit)));
  throw InputError(fmt::format("{} needs {}; this machine has {} (use --memory-limit to change the limit)",
                               what, format_estimate(bytes), format_bytes(limit)));
}

void check_triangle_estimate(double triangles, double bytes_per_triangle, const std::string& what) {
  check_memory_estimate(triangles * bytes_per_triangle, what);
  if (triangles >= 2147483648.0)
    throw InputError(what + ": more than 2^31 triangles, beyond the renderer's 32-bit indices");
}

}  // namespace ochre
