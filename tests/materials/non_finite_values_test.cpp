// NaN and infinities at shading time (docs/nodes.md, "Non-finite values"): every NodeArgs write, closure
// weight, lobe weight and emission is made finite (NaN -> 0, +-inf -> +-largest float) and counted once;
// finite values pass unchanged. Then every way a non-finite value can enter a material program (vertex
// colour, uv, a texel, arithmetic that overflows) into every closure: the lobes get finite weights and
// give finite values.

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <limits>

#include "material_test_support.h"
#include "materials/core/pcg32.h"
#include "materials/lobes/lambert.h"
#include "materials/nodes/node_args.h"
#include "support/awkward_floats.h"
#include "support/spectrum_lanes.h"

namespace ochre::test::non_finite_values_test {
namespace {

bool finite(const SampledSpectrum& s) {
  return s.is_finite();
}

// ------------------------------------------------------------------------------------- the boundary

class NodeArgsBoundary : public ::testing::Test {
 protected:
  NodeArgsBoundary() {
    ctx.lambda = &test_wavelengths();
    ctx.nonfinite = &tally;
  }
  NodeArgs args() { return NodeArgs(ctx, frame.data(), in.data(), out.data(), nullptr, ~0u, arena, closure); }
  // Two spectrum-wide inputs then two outputs (a float, colour or vector output uses the first floats of its
  // register).
  static constexpr int kIn1 = kSpectrumSamples, kOut0 = 2 * kSpectrumSamples, kOut1 = 3 * kSpectrumSamples;
  SampledSpectrum at(int offset) const {
    SampledSpectrum s;
    for (int k = 0; k < kSpectrumSamples; ++k) s[k] = frame[offset + k];
    return s;
  }

  std::array<float, 4 * kSpectrumSamples> frame{};
  std::array<uint16_t, 2> in{0, kIn1};
  std::array<uint16_t, 2> out{kOut0, kOut1};
  NonFiniteTally tally;
  ShadingContext ctx;
  LobeArena arena{1024};
  Closure closure;
};

TEST_F(NodeArgsBoundary, FiniteWritesAreUnchangedAndNotCounted) {
  const NodeArgs a = args();
  a.set_float(0, -0.0f);
  EXPECT_TRUE(std::signbit(frame[kOut0]));
  a.set_colour(0, {kLargest, 1e-45f, -kLargest});
  EXPECT_EQ(frame[kOut0], kLargest);
  EXPECT_EQ(frame[kOut0 + 1], 1e-45f);
  EXPECT_EQ(frame[kOut0 + 2], -kLargest);
  a.set_vector(1, {0.5f, -2.0f, 3e38f});
  EXPECT_EQ(frame[kOut1 + 2], 3e38f);
  a.set_spectrum(1, lanes({1.0f, 2.0f, 3.0f, 4.0f}));
  EXPECT_EQ(at(kOut1), lanes({1.0f, 2.0f, 3.0f, 4.0f}));
  EXPECT_EQ(tally.values, 0u);
}

TEST_F(NodeArgsBoundary, EachNonFiniteWriteIsMadeFiniteAndCountedOnce) {
  const NodeArgs a = args();
  a.set_float(0, kNaN);
  EXPECT_EQ(std::bit_cast<uint32_t>(frame[kOut0]), 0u);
  EXPECT_EQ(tally.values, 1u);
  a.set_colour(0, {kInf, 0.5f, kNaN});
  EXPECT_EQ(frame[kOut0], kLargest);
  EXPECT_EQ(frame[kOut0 + 1], 0.5f);
  EXPECT_EQ(frame[kOut0 + 2], 0.0f);
  EXPECT_EQ(tally.values, 2u);
  a.set_vector(1, {-kInf, 1.0f, 2.0f});
  EXPECT_EQ(frame[kOut1], -kLargest);
  EXPECT_EQ(tally.values, 3u);
  a.set_spectrum(1, lanes({kNaN, kInf, -kInf, 0.25f}));
  EXPECT_EQ(at(kOut1), lanes({0.0f, kLargest, -kLargest, 0.25f}));
  EXPECT_EQ(tally.values, 4u);
}

TEST_F(NodeArgsBoundary, ClosureWeightsThatOverflowAreLimited) {
  for (int k = 0; k < kSpectrumSamples; ++k) frame[k] = kLargest;
  args().add_weight(0, SampledSpectrum(kLargest));
  EXPECT_EQ(at(0), SampledSpectrum(kLargest));
  EXPECT_EQ(tally.values, 1u);
  args().add_weight(1, SampledSpectrum(0.5f));
  EXPECT_EQ(at(kIn1), SampledSpectrum(0.5f));
  EXPECT_EQ(tally.values, 1u);
}

TEST_F(NodeArgsBoundary, LobeWeightsAreFinite) {
  const NodeArgs a = args();
  const LambertLobe* lobe = arena.make<LambertLobe>();
  a.add_lobe(lobe, lanes({kInf, kNaN, 1.0f, 2.0f}));
  ASSERT_EQ(closure.lobe_count(), 1);
  EXPECT_EQ(closure.lobe(0).weight, lanes({kLargest, 0.0f, 1.0f, 2.0f}));
  a.add_lobe(lobe, SampledSpectrum(kNaN));  // all NaN: weight 0, so no lobe
  EXPECT_EQ(closure.lobe_count(), 1);
  a.add_lobe(lobe, SampledSpectrum(0.5f));
  EXPECT_EQ(closure.lobe(1).weight, SampledSpectrum(0.5f));
  EXPECT_EQ(tally.values, 2u);
}

TEST_F(NodeArgsBoundary, EmissionThatOverflowsWhenSummedIsLimited) {
  const NodeArgs a = args();
  a.add_emission(SampledSpectrum(kLargest));
  EXPECT_EQ(tally.values, 0u);
  a.add_emission(SampledSpectrum(kLargest));  // two finite emissions whose sum overflows
  EXPECT_EQ(closure.emission(), SampledSpectrum(kLargest));
  EXPECT_EQ(tally.values, 1u);
  a.add_emission(lanes({kNaN, 0.0f, 0.0f, 0.0f}));
  EXPECT_EQ(closure.emission(), lanes({0.0f, kLargest, kLargest, kLargest}));
  EXPECT_EQ(tally.values, 2u);
}

TEST_F(NodeArgsBoundary, WithoutATallyValuesAreStillMadeFinite) {
  ctx.nonfinite = nullptr;
  args().set_spectrum(0, SampledSpectrum(kInf));
  EXPECT_EQ(at(kOut0), SampledSpectrum(kLargest));
}

TEST_F(NodeArgsBoundary, ConstantFoldingKeepsTheValueToReportIt) {
  tally.keep_values = true;
  args().set_float(0, kInf);
  EXPECT_EQ(frame[kOut0], kInf);
  EXPECT_EQ(tally.values, 1u);
}

// ------------------------------------------------------------------------------------- entry points

// Every texel holds `value` (a NaN or an infinity).
class ConstantTextures : public TextureProvider {
 public:
  explicit ConstantTextures(float v) : value(v) {}
  void lookup(int, const Vec2&, float, int, int nchannels, float* out) const override {
    for (int k = 0; k < nchannels; ++k) out[k] = value;
  }
  float value;
};

class NonFiniteEntryPoints : public ::testing::Test {
 protected:
  // Compiles and evaluates the material; every lobe weight, the emission and the lobes' values and samples
  // in a few directions must be finite. Returns the number of values made finite.
  uint64_t evaluate_finite(const std::string& json_text, const TextureProvider* textures = nullptr) {
    const auto material = compile(json_text, resolver);
    const SampledWavelengths& lambda = test_wavelengths();
    ShadingContext c = ctx;
    c.lambda = &lambda;
    c.textures = textures;
    NonFiniteTally tally;
    c.nonfinite = &tally;
    LobeArena arena;
    Closure closure;
    material->evaluate(c, arena, closure);
    EXPECT_TRUE(finite(closure.emission())) << json_text;
    for (int i = 0; i < closure.lobe_count(); ++i) EXPECT_TRUE(finite(closure.lobe(i).weight)) << json_text;
    const Vec3 wo = normalize(Vec3{0.3f, -0.2f, 0.9f});
    Pcg32 rng(3);
    for (int n = 0; n < 16; ++n) {
      const Vec3 wi =
          normalize(Vec3{rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() + 0.01f});
      for (int i = 0; i < closure.lobe_count(); ++i) {
        const Lobe& lobe = *closure.lobe(i).lobe;
        EXPECT_TRUE(finite(lobe.eval(wo, wi, lambda))) << json_text;
        EXPECT_TRUE(std::isfinite(lobe.pdf(wo, wi, lambda))) << json_text;
        const auto s = lobe.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()}, lambda);
        if (!s) continue;
        EXPECT_TRUE(finite(s->weight)) << json_text;
        EXPECT_TRUE(std::isfinite(s->wi.x) && std::isfinite(s->wi.y) && std::isfinite(s->wi.z)) << json_text;
      }
    }
    return tally.values;
  }

  StubResolver resolver{"/scenes"};
  ShadingContext ctx;
};

// The issue's material: vertex colour x 3e38 x 10 is infinite.
constexpr const char* kOverflowingColour = R"(
    "vc": {"type": "vertex_colour"},
    "big": {"type": "multiply", "a": {"link": "vc.color"}, "b": 3e38},
    "inf": {"type": "multiply", "a": {"link": "big"}, "b": 10})";

std::string material_fed_by(const char* sources, const std::string& closure) {
  return std::string(R"({"nodes": {)") + sources + R"(, "out": )" + closure + R"(}, "output": "out"})";
}

TEST_F(NonFiniteEntryPoints, VertexColourOverflowingThroughMultiply) {
  EXPECT_GT(evaluate_finite(
                material_fed_by(kOverflowingColour, R"({"type": "lambert", "color": {"link": "inf"}})")),
            0u);
}

TEST_F(NonFiniteEntryPoints, OverflowThroughAdd) {
  const char* sources = R"(
      "vc": {"type": "vertex_colour"},
      "big": {"type": "multiply", "a": {"link": "vc.color"}, "b": 3e38},
      "sum": {"type": "add", "a": {"link": "big"}, "b": {"link": "big"}})";
  EXPECT_GT(evaluate_finite(material_fed_by(sources, R"({"type": "lambert", "color": {"link": "sum"}})")),
            0u);
}

TEST_F(NonFiniteEntryPoints, NonFiniteVertexColour) {
  ctx.vertex_colour = {kNaN, kInf, -kInf};
  EXPECT_EQ(evaluate_finite(R"({"nodes": {"vc": {"type": "vertex_colour"},
      "out": {"type": "lambert", "color": {"link": "vc.color"}}}, "output": "out"})"),
            1u);
}

TEST_F(NonFiniteEntryPoints, NonFiniteUvReachTheTextureFinite) {
  resolver.add_texture("t.exr", 3);
  StubTextures textures;  // returns the colour (u, v, 0.25)
  ctx.uv = {kNaN, kInf};
  EXPECT_EQ(evaluate_finite(R"({"nodes": {"t": {"type": "texture", "file": "t.exr"},
      "out": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "out"})",
                            &textures),
            1u);
  EXPECT_EQ(textures.last_uv.x, 0.0f);
  EXPECT_EQ(textures.last_uv.y, kLargest);
}

// Each closure fed NaN, +inf and -inf texels (through a colour and through a float input).
TEST_F(NonFiniteEntryPoints, EveryClosureFedNonFiniteTexels) {
  resolver.add_texture("t.exr", 3);
  const char* texture = R"("t": {"type": "texture", "file": "t.exr"})";
  const std::string closures[] = {
      R"({"type": "lambert", "color": {"link": "t.color"}})",
      R"({"type": "oren_nayar", "color": {"link": "t.color"}, "sigma": {"link": "t.value"}})",
      R"({"type": "lambert_sphere", "kd": {"link": "t.color"}})",
      R"({"type": "lambert_sphere", "particle_albedo": {"link": "t.color"}, "variant": "fast"})",
      R"({"type": "lambert_sphere", "kd": {"link": "t.color"}, "variant": "exact"})",
      R"({"type": "lambert_sphere", "kd": {"link": "t.color"}, "mapping": "eq46"})",
      R"({"type": "chandrasekhar", "albedo": {"link": "t.color"}})",
      R"({"type": "conductor", "eta": {"link": "t.value"}, "k": {"link": "t.value"}, "roughness": {"link": "t.value"}})",
      R"({"type": "conductor", "eta": {"link": "t.value"}, "k": {"link": "t.value"}})",
      R"({"type": "dielectric", "ior": {"link": "t.value"}, "roughness": {"link": "t.value"}})",
      R"({"type": "dielectric", "ior": {"link": "t.value"}})",
      R"({"type": "emission", "color": {"link": "t.color"}, "strength": {"link": "t.value"}})",
  };
  for (float texel : {kNaN, kInf, -kInf, 1e30f}) {
    const ConstantTextures textures(texel);
    for (const std::string& closure : closures) {
      SCOPED_TRACE("texel " + std::to_string(texel));
      const uint64_t count = evaluate_finite(material_fed_by(texture, closure), &textures);
      if (!std::isfinite(texel)) {
        EXPECT_GT(count, 0u) << closure;
      }
    }
  }
}

TEST_F(NonFiniteEntryPoints, EmissionFedAnOverflow) {
  EXPECT_GT(
      evaluate_finite(material_fed_by(kOverflowingColour, R"({"type": "emission", "color": {"link": "inf"},
                                                                   "strength": 3e38})")),
      0u);
}

TEST_F(NonFiniteEntryPoints, MixFactorFedNaN) {
  resolver.add_texture("t.exr", 1);
  const ConstantTextures textures(kNaN);
  EXPECT_GT(evaluate_finite(R"({"nodes": {"t": {"type": "texture", "file": "t.exr"},
      "a": {"type": "lambert", "color": 0.2}, "b": {"type": "lambert", "color": 0.6},
      "out": {"type": "mix", "a": {"link": "a"}, "b": {"link": "b"}, "factor": {"link": "t.value"}}},
      "output": "out"})",
                            &textures),
            0u);
}

}  // namespace
}  // namespace ochre::test::non_finite_values_test
