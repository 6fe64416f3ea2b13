// Cost per evaluation (float) of Lambert and the three LS variants, printed (a figure, not a pass/fail
// criterion: machine dependent). Also the exact table's memory.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <vector>

#include "materials/lobes/lambert.h"
#include "materials/lobes/lambert_sphere/lambert_sphere.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_exact.h"
#include "materials/lobes/lambert_sphere/lambert_sphere_lobe.h"
#include "support/spectrum_lanes.h"

namespace ochre::test::benchmark_test {
namespace {

struct Directions {
  std::vector<Vec3> wo, wi;
  explicit Directions(int n) {
    uint32_t s = 12345;
    auto next = [&] { return float((s = s * 1664525u + 1013904223u) >> 8) * 0x1p-24f; };
    for (int k = 0; k < n; ++k) {
      auto dir = [&] {
        const float mu = 0.01f + 0.99f * next(), phi = 6.2831853f * next(), r = std::sqrt(1 - mu * mu);
        return Vec3{r * std::cos(phi), r * std::sin(phi), mu};
      };
      wo.push_back(dir());
      wi.push_back(dir());
    }
  }
};

template <class F>
double ns_per_call(const Directions& d, F f) {
  volatile float sink = 0;
  const int repeats = 20;
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) {
    float acc = 0;
    for (size_t k = 0; k < d.wo.size(); ++k) acc += f(d.wo[k], d.wi[k]);
    sink = sink + acc;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return 1e9 * seconds / (double(repeats) * d.wo.size());
}

TEST(LambertSphereBenchmark, NanosecondsPerEvaluation) {
  const Directions d(50'000);
  const SampledWavelengths lambda = SampledWavelengths::fixed(lanes({400.0f, 500.0f, 600.0f, 700.0f}));
  const float c = 0.8f;
  const LambertSphereConstants<float> k = lambert_sphere_constants(c);
  const LambertSphereExactConstants ke = lambert_sphere_exact_constants(c);
  const LambertLobe lambert;
  const double t_lambert =
      ns_per_call(d, [&](const Vec3& wo, const Vec3& wi) { return lambert.eval(wo, wi, lambda)[0]; });
  const double t_full = ns_per_call(
      d, [&](const Vec3& wo, const Vec3& wi) { return lambert_sphere_full(k, wi.z, wo.z, dot(wi, wo)); });
  const double t_full_recompute = ns_per_call(d, [&](const Vec3& wo, const Vec3& wi) {
    return lambert_sphere_full(lambert_sphere_constants(c + 1e-9f * wo.x), wi.z, wo.z, dot(wi, wo));
  });
  const double t_fast = ns_per_call(
      d, [&](const Vec3& wo, const Vec3& wi) { return lambert_sphere_fast(k, wi.z, wo.z, dot(wi, wo)); });
  const double t_exact = ns_per_call(
      d, [&](const Vec3& wo, const Vec3& wi) { return lambert_sphere_exact(ke, wi.z, wo.z, dot(wi, wo)); });
  const SampledSpectrum cs = lanes({0.3f, 0.6f, 0.8f, 0.95f});
  const LambertSphereLobe full(LambertSphereVariant::kFull, cs), fast(LambertSphereVariant::kFast, cs),
      exact(LambertSphereVariant::kExact, cs);
  auto lobe_time = [&](const Lobe& lobe) {
    return ns_per_call(d, [&](const Vec3& wo, const Vec3& wi) { return lobe.eval(wo, wi, lambda)[1]; });
  };
  std::printf(
      "ns per float evaluation, one wavelength: Lambert lobe %.1f, full %.1f (constants recomputed per call: "
      "%.1f), fast %.1f, exact %.1f\n",
      t_lambert, t_full, t_full_recompute, t_fast, t_exact);
  std::printf("ns per lobe eval(), 4 wavelengths: full %.1f, fast %.1f, exact %.1f\n", lobe_time(full),
              lobe_time(fast), lobe_time(exact));
  std::printf("exact table: %zu bytes\n", lambert_sphere_exact_bytes());
  EXPECT_GT(t_full, 0.0);
}

}  // namespace
}  // namespace ochre::test::benchmark_test
