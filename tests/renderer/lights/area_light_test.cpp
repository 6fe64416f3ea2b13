// AreaLight: one-sided emission, and the per-thread reuse of a uniform material's emission for the
// wavelengths it was evaluated at (it must always equal a fresh evaluation of the material).

#include "renderer/lights/area_light.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "renderer/geometry/surface_shading.h"
#include "renderer/shapes/procedural_shapes.h"
#include "support/test_material.h"

namespace ochre::area_light_test {
namespace {

std::shared_ptr<const CompiledMaterial> material(const char* json) {
  return test::compile_test_material(json, "light");
}

SampledSpectrum fresh_emission(const CompiledMaterial& m, const SurfacePoint& sp,
                               const SampledWavelengths& l) {
  LobeArena arena;
  Closure closure;
  m.evaluate(shading_context(sp, {0, 0, 0}, l, nullptr), arena, closure);
  return closure.emission();
}

TEST(AreaLight, UniformEmissionIsReusedOnlyForTheSameLightAndWavelengths) {
  const Mesh plane = make_plane({1, 1});
  const auto warm = material(R"({"type": "emission", "color": [0.9, 0.5, 0.2], "strength": 3})");
  const auto cool = material(R"({"type": "emission", "color": [0.1, 0.4, 0.9], "strength": 2})");
  ASSERT_TRUE(warm->facts().uniform_over_surface);
  const AreaLight a(plane, *warm, nullptr), b(plane, *cool, nullptr);
  const SurfacePoint sp = surface_point(plane, 0, 0.2f, 0.3f);
  // More (light, wavelengths) pairs than cache entries, visited in an order that revisits each.
  const float us[] = {0.1f, 0.7f, 0.1f, 0.35f, 0.9f, 0.7f, 0.55f, 0.1f, 0.9f};
  for (float u : us) {
    const SampledWavelengths l = SampledWavelengths::sample_visible(u);
    EXPECT_EQ(a.emitted(sp, sp.ng, l), fresh_emission(*warm, sp, l)) << "u " << u;
    EXPECT_EQ(b.emitted(sp, sp.ng, l), fresh_emission(*cool, sp, l)) << "u " << u;
  }
  // A light made later at the same address is not served the old light's values.
  const SampledWavelengths l = SampledWavelengths::sample_visible(0.1f);
  {
    const AreaLight first(plane, *warm, nullptr);
    (void)first.emitted(sp, sp.ng, l);
  }
  const AreaLight second(plane, *cool, nullptr);
  EXPECT_EQ(second.emitted(sp, sp.ng, l), fresh_emission(*cool, sp, l));
}

TEST(AreaLight, EmissionIsOneSided) {
  const Mesh plane = make_plane({1, 1});
  const auto m = material(R"({"type": "emission", "strength": 3})");
  const AreaLight light(plane, *m, nullptr);
  const SurfacePoint sp = surface_point(plane, 1, 0.3f, 0.3f);
  const SampledWavelengths l = SampledWavelengths::sample_visible(0.4f);
  EXPECT_GT(light.emitted(sp, sp.ng, l)[0], 0.0f);
  EXPECT_EQ(light.emitted(sp, -sp.ng, l), SampledSpectrum(0.0f));
}

// An emitter whose material also has the most lobes a closure holds, each of the largest kind (Lambert
// sphere: per-wavelength constants): its emission is evaluated with room for all of them. With eight
// wavelengths per path these lobes outgrew the 4 KB the light once reserved (an internal error).
TEST(AreaLight, EmitterWithTheMostAndLargestLobesIsEvaluated) {
  std::string nodes, sum = "l0";
  for (int i = 0; i < Closure::kMaxLobes; ++i)
    nodes += fmt::format(R"("l{}": {{"type": "lambert_sphere"}}, )", i);
  for (int i = 1; i < Closure::kMaxLobes; ++i) {
    nodes += fmt::format(R"("a{}": {{"type": "add", "a": {{"link": "{}"}}, "b": {{"link": "l{}"}}}}, )", i,
                         sum, i);
    sum = fmt::format("a{}", i);
  }
  const std::string json = fmt::format(
      R"({{"nodes": {{{}"e": {{"type": "emission", "strength": 2}}, "out": {{"type": "add", "a": {{"link": "{}"}},
      "b": {{"link": "e"}}}}}}, "output": "out"}})",
      nodes, sum);
  const auto m = material(json.c_str());
  const Mesh plane = make_plane({1, 1});
  const AreaLight light(plane, *m, nullptr);
  const SurfacePoint sp = surface_point(plane, 0, 0.2f, 0.3f);
  const SampledWavelengths l = SampledWavelengths::sample_visible(0.3f);
  const SampledSpectrum e = light.emitted(sp, sp.ng, l);
  EXPECT_EQ(e, fresh_emission(*m, sp, l));
  EXPECT_GT(e[0], 0.0f);
}

}  // namespace
}  // namespace ochre::area_light_test
