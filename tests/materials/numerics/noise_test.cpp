// Procedural noise (materials/numerics/noise.h) and the nodes that read the shading point's position:
// position, noise and projection (docs/nodes.md).
#include "materials/numerics/noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/lobes/closure.h"
#include "materials/lobes/lobe_arena.h"
#include "materials/material_test_support.h"
#include "materials/nodes/shading_context.h"
#include "support/test_paths.h"

namespace ochre::test::noise_test {
namespace {

TEST(Noise, GradientNoiseIsZeroOnTheLatticeAndBoundedElsewhere) {
  for (int i = -3; i <= 3; ++i) EXPECT_EQ(gradient_noise(Vec3(float(i), float(2 * i), float(-i)), 7), 0.0f);
  float lo = 0, hi = 0;
  double sum = 0, sum2 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const Vec3 p(0.137f * i, 0.071f * i + 0.3f, -0.053f * i + 0.7f);
    const float v = gradient_noise(p, 3);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
    sum2 += double(v) * v;
  }
  EXPECT_GE(lo, -1.05f);
  EXPECT_LE(hi, 1.05f);
  EXPECT_LT(lo, -0.4f);  // it does vary
  EXPECT_GT(hi, 0.4f);
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  const double sd = std::sqrt(sum2 / n);
  EXPECT_GT(sd, 0.1);
  EXPECT_LT(sd, 0.4);
}

// The same bits on every machine and whichever instruction set the noise runs on (it is built for AVX2 and
// for baseline x86-64, materials/core/vector_clones.h): values recorded from the scalar build before the
// vector one existed.
TEST(Noise, ValuesAreTheRecordedBits) {
  const FractalNoise five_octaves{5, 2.0f, 0.5f};
  EXPECT_EQ(gradient_noise(Vec3(0.3f, 0.7f, 0.1f), 7), -0x1.15aa64p-2f);
  EXPECT_EQ(gradient_noise(Vec3(-12.25f, 3.5f, 8.75f), 7), 0x1.36cfcp-3f);
  EXPECT_EQ(gradient_noise(Vec3(1234.5f, -77.1f, 0.001f), 7), -0x1.6c9b5cp-5f);
  EXPECT_EQ(fractal_noise(Vec3(0.3f, 0.7f, 0.1f), five_octaves, 3), -0x1.97a102p-3f);
  EXPECT_EQ(fractal_noise(Vec3(-12.25f, 3.5f, 8.75f), five_octaves, 3), 0x1.07bfbep-3f);
  EXPECT_EQ(fractal_noise(Vec3(1234.5f, -77.1f, 0.001f), five_octaves, 3), 0x1.3115d8p-4f);
}

TEST(Noise, IsContinuousDeterministicAndSeeded) {
  const Vec3 p(1.234f, -5.678f, 9.1011f);
  EXPECT_EQ(gradient_noise(p, 1), gradient_noise(p, 1));
  EXPECT_NE(gradient_noise(p, 1), gradient_noise(p, 2));
  // Lipschitz: the gradient of Perlin noise is bounded (a few units), so a step of 1e-3 moves it little.
  for (int i = 0; i < 1000; ++i) {
    const Vec3 q(0.31f * i, 0.17f * i, 0.05f * i);
    EXPECT_LT(std::fabs(gradient_noise(q + Vec3(1e-3f, 0, 0), 5) - gradient_noise(q, 5)), 0.01f);
  }
  // Across a cell border (x = 1) from both sides.
  EXPECT_NEAR(gradient_noise({0.99999f, 0.3f, 0.6f}, 9), gradient_noise({1.00001f, 0.3f, 0.6f}, 9), 1e-3f);
}

TEST(Noise, FractalNoiseStaysInUnitRange) {
  const FractalNoise fractal{8, 2.0f, 0.7f};
  for (int i = 0; i < 50000; ++i) {
    const float v = fractal_noise(Vec3(0.11f * i, 0.37f * i, 0.013f * i), fractal, 4);
    EXPECT_LE(std::fabs(v), 1.0f);
  }
  // One octave is the gradient noise itself (its own seed).
  const Vec3 p(0.4f, 0.2f, 0.9f);
  EXPECT_NE(fractal_noise(p, {1, 2.0f, 0.5f}, 0), 0.0f);
}

TEST(Noise, CellDistancesAreOrderedAndZeroAtAFeature) {
  float smallest = 1;
  for (int i = 0; i < 20000; ++i) {
    const CellDistances c = cell_noise(Vec3(0.013f * i, 0.029f * i, 0.007f * i), 2);
    EXPECT_LE(c.f1, c.f2);
    EXPECT_LT(c.f1, std::sqrt(3.0f));
    smallest = std::min(smallest, c.f1);
  }
  EXPECT_LT(smallest, 0.05f);  // the walk passes near feature points
}

TEST(Noise, RockHeightAddsFlowstoneAndCutsCracks) {
  RockNoise plain;
  plain.seed = 3;
  RockNoise cracked = plain;
  cracked.cracks = 1.0f;
  RockNoise draped = plain;
  draped.flowstone = 1.0f;
  int cut = 0, raised = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p(0.021f * i, 0.5f + 0.003f * i, -0.017f * i);
    const float h = rock_height(p, plain);
    EXPECT_LE(rock_height(p, cracked), h);  // cracks only cut
    EXPECT_GE(rock_height(p, draped), h);   // flowstone only adds
    cut += rock_height(p, cracked) < h - 0.5f;
    raised += rock_height(p, draped) > h + 0.2f;
  }
  // Cracks are narrow lines: a few per cent of the points, not most.
  EXPECT_GT(cut, 100);
  EXPECT_LT(cut, 6000);
  EXPECT_GT(raised, 100);
}

// --- Nodes ---------------------------------------------------------------------------------------------

using PositionNodes = MaterialEvaluation;

TEST_F(PositionNodes, NoiseOfThePositionDrivesAMix) {
  ctx.p = {0.3f, 1.7f, -2.2f};
  const Closure& c = evaluate(R"({"nodes": {
      "n": {"type": "noise", "frequency": 2, "octaves": 3, "seed": 5},
      "d": {"type": "lambert", "color": {"link": "n"}}}, "output": "d"})");
  const float expected = 0.5f + 0.5f * fractal_noise(ctx.p * 2.0f, {3, 2.0f, 0.5f}, 5);
  EXPECT_FLOAT_EQ(c.lobe(0).weight[0], expected);
  EXPECT_FALSE(material->facts().uniform_over_surface);
}

TEST_F(PositionNodes, CrackNoiseIsOneOnCellBordersAndZeroInside) {
  int borders = 0, inside = 0;
  for (int i = 0; i < 400; ++i) {
    ctx.p = {0.037f * i, 0.011f * i, -0.023f * i};
    const CellDistances cells = cell_noise(ctx.p * 3.0f, 0);
    const Closure& c = evaluate(R"({"nodes": {
        "n": {"type": "noise", "pattern": "cracks", "frequency": 3, "width": 0.2},
        "d": {"type": "lambert", "color": {"link": "n"}}}, "output": "d"})");
    const float value = c.lobe_count() ? c.lobe(0).weight[0] : 0.0f;
    const float t = std::fmin(1.0f, (cells.f2 - cells.f1) / 0.2f);
    EXPECT_NEAR(value, 1.0f - t * t * (3.0f - 2.0f * t), 1e-6f);
    borders += value > 0.99f;
    inside += value == 0.0f;
  }
  EXPECT_GT(borders, 0);
  EXPECT_GT(inside, 100);  // most points are farther than the width from a border
}

TEST_F(PositionNodes, ProjectionMapsTheFrameToUnitSquareAndMasksOutside) {
  resolver.add_texture("mask.png", 1);
  auto lookup_at = [&](const Vec3& p) {
    ctx.p = p;
    ctx.footprint = 0.02f;
    return evaluate(R"({"nodes": {
        "f": {"type": "projection", "origin": [1, 0, -2], "u_axis": [2, 0, 0], "v_axis": [0, 4, 0], "depth": 0.5},
        "t": {"type": "texture", "file": "mask.png", "uv": {"link": "f.uv"}, "footprint": {"link": "f.footprint"}},
        "inside": {"type": "multiply", "a": {"link": "f.inside"}, "b": 1},
        "d": {"type": "lambert", "color": {"link": "inside"}},
        "t_used": {"type": "lambert", "color": {"link": "t.color"}},
        "out": {"type": "add", "a": {"link": "d"}, "b": {"link": "t_used"}}}, "output": "out"})");
  };
  lookup_at({2.0f, 1.0f, -2.3f});  // u = 0.5, v = 0.25, 0.3 behind the plane
  EXPECT_FLOAT_EQ(textures.last_uv.x, 0.5f);
  EXPECT_FLOAT_EQ(textures.last_uv.y, 0.25f);
  EXPECT_FLOAT_EQ(textures.last_footprint, 0.02f / 2.0f);  // over the shorter axis
  EXPECT_EQ(closure.lobe_count(), 2);                      // inside: the mask lobe has weight 1
  lookup_at({2.0f, 1.0f, -2.6f});                          // 0.6 from the plane: beyond depth
  EXPECT_EQ(closure.lobe_count(), 1);
  lookup_at({3.5f, 1.0f, -2.0f});  // u = 1.25: outside the frame
  EXPECT_EQ(closure.lobe_count(), 1);
  EXPECT_FLOAT_EQ(textures.last_uv.x, 1.25f);
}

// A mask multiplied by its projection's `inside` is not looked up outside the frame (its instruction is
// gated, docs/nodes.md): the result is the same as if it had been, 0.
TEST_F(PositionNodes, ProjectedMaskIsLookedUpOnlyInsideItsFrame) {
  resolver.add_texture("mask.png", 1);
  const auto m = compile(R"({"nodes": {
      "f": {"type": "projection", "origin": [1, 0, -2], "u_axis": [2, 0, 0], "v_axis": [0, 4, 0], "depth": 0.5},
      "t": {"type": "texture", "file": "mask.png", "uv": {"link": "f.uv"}},
      "cover": {"type": "multiply", "a": {"link": "t.value"}, "b": {"link": "f.inside"}},
      "rock": {"type": "lambert", "color": 0.5},
      "paint": {"type": "lambert", "color": 0.1},
      "out": {"type": "mix", "a": {"link": "rock"}, "b": {"link": "paint"}, "factor": {"link": "cover"}}},
      "output": "out"})",
                         resolver);
  ctx.p = {2.0f, 1.0f, -2.3f};  // inside: u = 0.5, so the stub mask's value is 0.5
  const Closure& inside = evaluate(*m);
  EXPECT_EQ(textures.lookups, 1);
  ASSERT_EQ(inside.lobe_count(), 2);
  EXPECT_FLOAT_EQ(inside.lobe(0).weight[0] + inside.lobe(1).weight[0], 0.5f * 0.5f + 0.5f * 0.1f);
  ctx.p = {3.5f, 1.0f, -2.0f};  // u = 1.25: outside the frame
  const Closure& outside = evaluate(*m);
  EXPECT_EQ(textures.lookups, 1) << "no lookup outside the frame";
  ASSERT_EQ(outside.lobe_count(), 1);
  EXPECT_EQ(outside.lobe(0).weight[0], 0.5f);
}

TEST_F(PositionNodes, ProjectionRejectsParallelAxes) {
  EXPECT_THROW(
      compile(
          R"({"nodes": {"f": {"type": "projection", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [2, 0, 0]},
      "d": {"type": "lambert", "color": {"link": "f.inside"}}}, "output": "d"})",
          resolver),
      std::exception);
  EXPECT_THROW(
      compile(
          R"({"nodes": {"f": {"type": "projection", "origin": 3, "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]},
      "d": {"type": "lambert", "color": {"link": "f.inside"}}}, "output": "d"})",
          resolver),
      std::exception);
}

TEST_F(PositionNodes, PositionNodeReadsTheWorldPosition) {
  ctx.p = {0.25f, 0.5f, 0.75f};
  const Closure& c = evaluate(R"({"nodes": {
      "p": {"type": "position"},
      "x": {"type": "multiply", "a": {"link": "p"}, "b": 1},
      "f": {"type": "projection", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0], "position": {"link": "x"}},
      "d": {"type": "lambert", "color": {"link": "f.inside"}}}, "output": "d"})");
  EXPECT_EQ(c.lobe_count(), 1);
}

}  // namespace
}  // namespace ochre::test::noise_test
