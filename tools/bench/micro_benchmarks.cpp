#include "tools/bench/micro_benchmarks.h"

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <memory>
#include <utility>

#include "materials/core/pcg32.h"
#include "materials/core/pi.h"
#include "materials/core/sampling.h"
#include "materials/lobes/lambert.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "renderer/geometry/accel.h"
#include "renderer/geometry/transform.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/sampling/sampler.h"
#include "renderer/sampling/sobol_sampler.h"
#include "renderer/shapes/control_mesh.h"
#include "renderer/shapes/mesh_import.h"
#include "renderer/shapes/subdivision.h"
#include "spectra/input_error.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre::bench {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// "12.3 ns (min 12.1, max 13.0)": the median of the rounds, then their range.
std::string figure(const Spread& s, int repeat, const char* unit, int decimals = 1) {
  if (repeat < 2) return fmt::format("{:.{}f} {}", s.median, decimals, unit);
  return fmt::format("{:.{}f} {} (min {:.{}f}, max {:.{}f})", s.median, decimals, unit, s.min, decimals,
                     s.max, decimals);
}

// ---------------------------------------------------------------- sobol
// The cost of one get_2d of each sampler, a quarter of a constructor included (4 dimensions per sampler,
// as a path vertex draws several): 2^20 samplers of 64 pixels' worth of sample indices.
void micro_sobol(const MicroOptions& options) {
  constexpr int kSamples = 1 << 20;
  constexpr uint64_t kSeed = 12345;
  constexpr std::array<uint32_t, 4> kDims = {1, 7, 15, 23};
  double sink = 0;
  auto time_ns = [&](auto make) {
    const auto start = Clock::now();
    for (int i = 0; i < kSamples; ++i) {
      const auto sampler = make(static_cast<uint64_t>(i));
      for (uint32_t d : kDims) {
        const Vec2 v = sampler.get_2d(d);
        sink += v.x + v.y;
      }
    }
    return 1e9 * seconds_since(start) / (kSamples * static_cast<double>(kDims.size()));
  };
  fmt::print(
      "sobol: get_2d of dimensions 1, 7, 15, 23 on 2^20 samplers (a quarter of a constructor "
      "included), 1 thread, {} round(s)\n",
      options.repeat);
  std::fflush(stdout);
  std::vector<double> sobol, independent;
  for (int round = 0; round < options.repeat; ++round) {
    sobol.push_back(time_ns([](uint64_t i) { return SobolSampler(kSeed, i >> 6, i); }));
    independent.push_back(time_ns([](uint64_t i) { return IndependentSampler(kSeed, i >> 6, i); }));
  }
  const Spread s = spread(sobol), r = spread(independent);
  fmt::print("  sobol        {}\n", figure(s, options.repeat, "ns per get_2d"));
  fmt::print("  independent  {}\n", figure(r, options.repeat, "ns per get_2d"));
  fmt::print("  sobol / independent: {:.2f}x (checksum {:.6g})\n", r.median > 0 ? s.median / r.median : 0.0,
             sink);
}

// ---------------------------------------------------------------- lambert-sphere
// Random direction pairs in the upper hemisphere (mu >= 0.01), from a fixed LCG.
struct DirectionPairs {
  std::vector<Vec3> wo, wi;
  explicit DirectionPairs(int n) {
    uint32_t state = 12345;
    auto next = [&] { return static_cast<float>((state = state * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
    auto direction = [&] {
      const float mu = 0.01f + 0.99f * next(), phi = 2 * kPi * next(), r = std::sqrt(1 - mu * mu);
      return Vec3{r * std::cos(phi), r * std::sin(phi), mu};
    };
    for (int k = 0; k < n; ++k) {
      wo.push_back(direction());
      wi.push_back(direction());
    }
  }
};

// ns per call of f over every pair, 20 passes.
double ns_per_call(const DirectionPairs& d, const std::function<float(const Vec3&, const Vec3&)>& f) {
  constexpr int kPasses = 20;
  volatile float sink = 0;
  const auto start = Clock::now();
  for (int pass = 0; pass < kPasses; ++pass) {
    float acc = 0;
    for (size_t k = 0; k < d.wo.size(); ++k) acc += f(d.wo[k], d.wi[k]);
    sink = sink + acc;
  }
  return 1e9 * seconds_since(start) / (static_cast<double>(kPasses) * static_cast<double>(d.wo.size()));
}

SampledSpectrum repeated_lanes(std::initializer_list<float> values) {
  SampledSpectrum s;
  const float* v = values.begin();
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = v[static_cast<size_t>(i) % values.size()];
  return s;
}

void micro_lambert_sphere(const MicroOptions& options) {
  constexpr int kPairs = 50'000;
  constexpr float kAlbedo = 0.8f;
  const DirectionPairs d(kPairs);
  const SampledWavelengths lambda =
      SampledWavelengths::fixed(repeated_lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  const LambertSphereConstants<float> k = lambert_sphere_constants(kAlbedo);
  const LambertSphereExactConstants ke = lambert_sphere_exact_constants(kAlbedo);
  const LambertLobe lambert;
  const SampledSpectrum albedos = repeated_lanes({0.3f, 0.6f, 0.8f, 0.95f});
  const LambertSphereLobe full(LambertSphereVariant::kFull, albedos),
      fast(LambertSphereVariant::kFast, albedos), exact(LambertSphereVariant::kExact, albedos);
  auto lobe = [&](const Lobe& l) {
    return [&l, &lambda](const Vec3& wo, const Vec3& wi) { return l.eval(wo, wi, lambda)[1]; };
  };
  const std::vector<std::pair<std::string, std::function<float(const Vec3&, const Vec3&)>>> cases = {
      {"one wavelength, Lambert lobe",
       [&](const Vec3& wo, const Vec3& wi) { return lambert.eval(wo, wi, lambda)[0]; }},
      {"one wavelength, full",
       [&](const Vec3& wo, const Vec3& wi) { return lambert_sphere_full(k, wi.z, wo.z, dot(wi, wo)); }},
      {"one wavelength, full, constants per call",
       [&](const Vec3& wo, const Vec3& wi) {
         return lambert_sphere_full(lambert_sphere_constants(kAlbedo + 1e-9f * wo.x), wi.z, wo.z,
                                    dot(wi, wo));
       }},
      {"one wavelength, fast",
       [&](const Vec3& wo, const Vec3& wi) { return lambert_sphere_fast(k, wi.z, wo.z, dot(wi, wo)); }},
      {"one wavelength, exact",
       [&](const Vec3& wo, const Vec3& wi) { return lambert_sphere_exact(ke, wi.z, wo.z, dot(wi, wo)); }},
      {fmt::format("lobe eval(), {} wavelengths, full", kSpectrumSamples), lobe(full)},
      {fmt::format("lobe eval(), {} wavelengths, fast", kSpectrumSamples), lobe(fast)},
      {fmt::format("lobe eval(), {} wavelengths, exact", kSpectrumSamples), lobe(exact)},
      // What a shading point pays: the lobe's constants for each wavelength, then one evaluation.
      {fmt::format("lobe built + eval(), {} wavelengths, full", kSpectrumSamples),
       [&](const Vec3& wo, const Vec3& wi) {
         return LambertSphereLobe(LambertSphereVariant::kFull, albedos * (1.0f - 0.01f * wo.z))
             .eval(wo, wi, lambda)[1];
       }},
  };
  fmt::print(
      "lambert-sphere: ns per float evaluation, {} random direction pairs x 20, c = {}, 1 thread, "
      "{} round(s)\n",
      kPairs, kAlbedo, options.repeat);
  std::fflush(stdout);
  std::vector<std::vector<double>> times(cases.size());
  for (int round = 0; round < options.repeat; ++round)
    for (size_t c = 0; c < cases.size(); ++c) times[c].push_back(ns_per_call(d, cases[c].second));
  for (size_t c = 0; c < cases.size(); ++c)
    fmt::print("  {:<42} {}\n", cases[c].first, figure(spread(times[c]), options.repeat, "ns"));
  fmt::print("  exact table: {} bytes\n", lambert_sphere_exact_bytes());
}

// ---------------------------------------------------------------- subdivision
void micro_subdivision(const MicroOptions& options) {
  constexpr int kLevel = 5;
  const ControlMesh grid = quad_grid_control_mesh(25, 20);
  fmt::print("subdivision: Catmull-Clark, {} quads with uvs to level {}, {} round(s)\n", grid.face_count(),
             kLevel, options.repeat);
  std::fflush(stdout);
  std::vector<double> seconds;
  size_t triangles = 0, vertices = 0;
  for (int round = 0; round < options.repeat; ++round) {
    const auto start = Clock::now();
    const Mesh mesh = subdivide(grid, {SubdivisionScheme::CatmullClark, kLevel});
    seconds.push_back(seconds_since(start));
    triangles = mesh.triangle_count();
    vertices = mesh.vertex_count();
  }
  const Spread s = spread(seconds);
  fmt::print("  {} triangles, {} vertices in {}: {:.2f} M triangles/s\n", triangles, vertices,
             figure(s, options.repeat, "s", 3),
             s.median > 0 ? static_cast<double>(triangles) / s.median * 1e-6 : 0.0);
}

// ---------------------------------------------------------------- bvh-build
// The meshes of a file: a scene's (.json) or one imported mesh, with the spare capacity that lets the Accel
// share its positions with Embree (as every mesh the renderer makes).
std::vector<Mesh> meshes_of(const std::string& file) {
  if (fs::path(file).extension() == ".json") {
    LoadedScene loaded = load_scene(file);
    return std::move(loaded.scene->meshes);
  }
  std::vector<Mesh> meshes;
  meshes.push_back(import_mesh(file, Transform::identity()));
  meshes.back().reserve_vertex_padding();
  return meshes;
}

void bvh_build(const std::string& file, const MicroOptions& options, tbb::task_arena& arena) {
  const auto load_start = Clock::now();
  const std::vector<Mesh> meshes = meshes_of(file);
  const double load_seconds = seconds_since(load_start);
  size_t triangles = 0, mesh_bytes = 0;
  Mesh::Bounds bounds;
  for (const Mesh& mesh : meshes) {
    triangles += mesh.triangle_count();
    mesh_bytes += mesh.positions.size() * sizeof(Vec3) + mesh.indices.size() * sizeof(uint32_t);
    if (mesh.triangle_count()) bounds.include(mesh.bounds());
  }
  if (triangles == 0)
    throw InputError(file + ": no triangle to build a BVH of (ochre-bench --micro bvh-build)");
  fmt::print("{}: {} mesh(es), {} triangles, loaded in {:.3f} s{}; BVH built on {} threads, {} round(s)\n",
             file, meshes.size(), triangles, load_seconds,
             fs::path(file).extension() == ".json" ? " (the whole scene)" : "", arena.max_concurrency(),
             options.repeat);
  std::fflush(stdout);
  std::vector<double> build_seconds;
  std::unique_ptr<Accel> accel;
  for (int round = 0; round < options.repeat; ++round) {
    accel.reset();
    arena.execute([&] { accel = std::make_unique<Accel>(meshes); });
    build_seconds.push_back(accel->build_seconds());
  }
  std::vector<double> build_ms;
  for (double seconds : build_seconds) build_ms.push_back(1e3 * seconds);
  const Spread build = spread(build_seconds);
  const double per_triangle = static_cast<double>(accel->memory_bytes()) / static_cast<double>(triangles);
  fmt::print("  BVH build {}: {:.2f} M triangles/s\n", figure(spread(build_ms), options.repeat, "ms", 2),
             build.median > 0 ? static_cast<double>(triangles) / build.median * 1e-6 : 0.0);
  fmt::print(
      "  memory {:.3f} MB = {:.1f} bytes/triangle (incl. {:.1f} of shared mesh arrays); {} mesh(es) copied\n",
      static_cast<double>(accel->memory_bytes()) * 1e-6, per_triangle,
      static_cast<double>(mesh_bytes) / static_cast<double>(triangles), accel->copied_vertex_buffers());
  // Incoherent rays from a sphere around the bounding box towards a ball at its centre, one thread.
  const Vec3 centre = (bounds.lo + bounds.hi) * 0.5f;
  const float radius = 0.5f * length(bounds.hi - bounds.lo);
  Pcg32 random(12345);
  auto uniform_2d = [&] { return Vec2{random.next_float(), random.next_float()}; };
  std::vector<Ray> rays(200000);
  for (Ray& ray : rays) {
    const Vec3 origin = centre + sample_uniform_sphere(uniform_2d()) * (2 * radius);
    const Vec3 target =
        centre + sample_uniform_sphere(uniform_2d()) * (0.5f * radius * std::cbrt(random.next_float()));
    ray = {origin, target - origin};
  }
  std::vector<double> rates;
  size_t hits = 0;
  for (int round = 0; round < options.repeat; ++round) {
    hits = 0;
    const auto start = Clock::now();
    for (const Ray& ray : rays) hits += accel->intersect(ray).has_value();
    rates.push_back(static_cast<double>(rays.size()) / seconds_since(start) * 1e-6);
  }
  fmt::print("  incoherent rays, 1 thread: {} ({:.0f} % hit)\n",
             figure(spread(rates), options.repeat, "M rays/s", 2),
             100.0 * static_cast<double>(hits) / static_cast<double>(rays.size()));
}

void micro_bvh_build(const MicroOptions& options) {
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  for (const std::string& file : options.files) {
    bvh_build(file, options, arena);
    std::fflush(stdout);
  }
}

}  // namespace

const std::vector<std::string>& micro_benchmark_names() {
  static const std::vector<std::string> names = {"sobol", "lambert-sphere", "subdivision", "bvh-build"};
  return names;
}

void run_micro_benchmark(const std::string& name, const MicroOptions& options) {
  if (name == "sobol")
    micro_sobol(options);
  else if (name == "lambert-sphere")
    micro_lambert_sphere(options);
  else if (name == "subdivision")
    micro_subdivision(options);
  else if (name == "bvh-build")
    micro_bvh_build(options);
  else
    throw InputError("--micro " + name + ": no such micro-benchmark");
  std::fflush(stdout);
}

}  // namespace ochre::bench
