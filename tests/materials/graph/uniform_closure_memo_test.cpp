// evaluate_memoized(): a material uniform over the surface is evaluated once per thread and set of
// wavelengths, and the memo gives the closure evaluate() gives; other materials are evaluated every time.

#include "materials/graph/uniform_closure_memo.h"

#include <gtest/gtest.h>

#include "materials/material_test_support.h"

namespace ochre::test::uniform_closure_memo_test {
namespace {

void expect_same_closure(const Closure& a, const Closure& b, const SampledWavelengths& lambda) {
  ASSERT_EQ(a.lobe_count(), b.lobe_count());
  EXPECT_EQ(a.emission(), b.emission());
  const Vec3 wo = normalize(Vec3(0.3f, -0.2f, 0.9f)), wi = normalize(Vec3(-0.5f, 0.1f, 0.7f));
  for (int i = 0; i < a.lobe_count(); ++i) {
    EXPECT_EQ(a.lobe(i).weight, b.lobe(i).weight);
    EXPECT_EQ(a.lobe(i).lobe->eval(wo, wi, lambda), b.lobe(i).lobe->eval(wo, wi, lambda));
  }
}

class UniformClosureMemo : public MaterialEvaluation {
 protected:
  UniformClosureMemo() {
    ctx.lambda = &lambda;
    ctx.textures = &textures;
  }
};

TEST_F(UniformClosureMemo, AUniformMaterialIsEvaluatedOncePerWavelengths) {
  const auto m = compile(R"({"type": "lambert", "color": [0.2, 0.5, 0.7]})");
  ASSERT_TRUE(m->facts().uniform_over_surface);
  m->evaluate(ctx, arena, closure);
  LobeArena other(1024);
  Closure first, second;
  evaluate_memoized(*m, ctx, other, first);
  expect_same_closure(first, closure, lambda);
  ctx.p = Vec3(5, 6, 7);  // the point does not matter to this material
  evaluate_memoized(*m, ctx, other, second);
  expect_same_closure(second, closure, lambda);
  ASSERT_EQ(second.lobe_count(), 1);
  EXPECT_EQ(second.lobe(0).lobe, first.lobe(0).lobe) << "the second call reuses the memo's lobe";

  // Other wavelengths: evaluated again, with their own values.
  const SampledWavelengths other_lambda = SampledWavelengths::sample_visible(0.37f);
  ctx.lambda = &other_lambda;
  Closure third;
  evaluate_memoized(*m, ctx, other, third);
  m->evaluate(ctx, arena, closure);
  expect_same_closure(third, closure, other_lambda);
  EXPECT_NE(third.lobe(0).weight, second.lobe(0).weight);
}

TEST_F(UniformClosureMemo, AMaterialThatReadsThePointIsEvaluatedEveryTime) {
  const auto m = compile(R"({"nodes": {"vc": {"type": "vertex_colour"},
      "out": {"type": "lambert", "color": {"link": "vc.color"}}}, "output": "out"})");
  ASSERT_FALSE(m->facts().uniform_over_surface);
  Closure a, b;
  ctx.vertex_colour = {0.1f, 0.2f, 0.3f};
  evaluate_memoized(*m, ctx, arena, a);
  ctx.vertex_colour = {0.9f, 0.8f, 0.7f};
  evaluate_memoized(*m, ctx, arena, b);
  m->evaluate(ctx, arena, closure);
  expect_same_closure(b, closure, lambda);
  ASSERT_EQ(a.lobe_count(), 1);
  EXPECT_NE(a.lobe(0).weight, b.lobe(0).weight);
}

// The values the first evaluation made finite are counted again on every reuse, as if it had run.
TEST_F(UniformClosureMemo, ReusesCountTheNonFiniteValuesOfTheEvaluation) {
  const auto m = compile(R"({"nodes": {
      "a": {"type": "emission", "color": 1, "strength": 3e38},
      "b": {"type": "emission", "color": 1, "strength": 3e38},
      "out": {"type": "add", "a": {"link": "a"}, "b": {"link": "b"}}}, "output": "out"})");
  ASSERT_TRUE(m->facts().uniform_over_surface);
  NonFiniteTally once, memoized;
  ctx.nonfinite = &once;
  m->evaluate(ctx, arena, closure);
  ASSERT_GT(once.values, 0u);
  ctx.nonfinite = &memoized;
  const SampledWavelengths fresh = SampledWavelengths::sample_visible(0.81f);  // not in this thread's memo
  ctx.lambda = &fresh;
  Closure c;
  for (int i = 0; i < 3; ++i) evaluate_memoized(*m, ctx, arena, c);
  EXPECT_EQ(memoized.values, 3 * once.values);
}

}  // namespace
}  // namespace ochre::test::uniform_closure_memo_test
