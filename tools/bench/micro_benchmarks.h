#pragma once
// The micro-benchmarks of `ochre-bench --micro NAME` (docs/tools.md, "Micro-benchmarks"): each times one
// part of the libraries alone, `repeat` rounds, and prints the median with the range of the rounds. They
// print figures and never judge them (timings depend on the machine and its load), which is why they live
// here and not in the unit tests (docs/architecture.md, "Tests").
//   sobol           SobolSampler::get_2d against IndependentSampler::get_2d (renderer/sampling)
//   lambert-sphere  ns per evaluation of Lambert and the three Lambertian-sphere variants (materials/lobes)
//   subdivision     Catmull-Clark refinement of a 500-quad grid to level 5, 1 M triangles (renderer/shapes)
//   bvh-build       the Accel's BVH build, memory and one-thread incoherent rays/s of meshes or scenes
//                   (renderer/geometry)

#include <algorithm>
#include <string>
#include <vector>

namespace ochre::bench {

// Median and range of a set of measurements.
struct Spread {
  double median = 0, min = 0, max = 0;
};
inline Spread spread(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v.front(), v.back()};
}

struct MicroOptions {
  int repeat = 3;                  // rounds; the median and range are printed
  int threads = 0;                 // threads of the BVH build (0 = all cores); the rest runs on one thread
  std::vector<std::string> files;  // bvh-build: meshes (any format import_mesh reads) or scenes (.json)
};

// The names --micro accepts, in the order `all` runs them.
const std::vector<std::string>& micro_benchmark_names();

// Runs the micro-benchmark `name` (one of micro_benchmark_names()) and prints its figures on stdout.
// Throws InputError for a file bvh-build cannot read.
void run_micro_benchmark(const std::string& name, const MicroOptions& options);

}  // namespace ochre::bench
