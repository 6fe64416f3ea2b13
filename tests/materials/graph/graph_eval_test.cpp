// Evaluation of compiled materials: closure weights and emission follow OSL's closure algebra,
// colours are upsampled by the role of the socket they reach, textures and vertex colours flow
// through the ShadingContext.

#include <gtest/gtest.h>

#include <fstream>

#include "materials/lobes/lambert.h"
#include "materials/material_test_support.h"
#include "materials/nodes/rgb_upsampling.h"
#include "spectra/cie.h"
#include "spectra/named_spectra.h"
#include "spectra/rgb_spectrum.h"
#include "support/spectrum_lanes.h"
#include "support/test_paths.h"

namespace ochre::test::graph_eval_test {
namespace {

class GraphEval : public MaterialEvaluation {
 protected:
  static void expect_spectrum_eq(const SampledSpectrum& actual, const SampledSpectrum& expected,
                                 float tolerance = 0.0f) {
    for (int k = 0; k < kSpectrumSamples; ++k) {
      if (tolerance == 0.0f)
        EXPECT_EQ(actual[k], expected[k]) << "lane " << k;
      else
        EXPECT_NEAR(actual[k], expected[k], tolerance * std::abs(expected[k])) << "lane " << k;
    }
  }
};

TEST_F(GraphEval, LambertFloatGivesOneLobeOfThatWeight) {
  const Closure& c = evaluate(R"({"type": "lambert", "color": 0.5})");
  ASSERT_EQ(c.lobe_count(), 1);
  expect_spectrum_eq(c.lobe(0).weight, SampledSpectrum(0.5f));
  EXPECT_EQ(c.lobe(0).lobe->flags(), LambertLobe().flags());
  EXPECT_TRUE(c.emission().is_black());
}

TEST_F(GraphEval, WhiteReflectanceIsExactlyOne) {
  expect_spectrum_eq(evaluate(R"({"type": "lambert", "color": [1, 1, 1]})").lobe(0).weight,
                     SampledSpectrum(1.0f));
  expect_spectrum_eq(evaluate(R"({"type": "lambert", "color": [0.3, 0.3, 0.3]})").lobe(0).weight,
                     SampledSpectrum(0.3f));
}

TEST_F(GraphEval, DefaultLambertAlbedoIs08) {
  expect_spectrum_eq(evaluate(R"({"type": "lambert"})").lobe(0).weight, SampledSpectrum(0.8f));
}

TEST_F(GraphEval, ColouredReflectanceIsTheAlbedoSpectrum) {
  const RGB rgb{0.8f, 0.2f, 0.1f};
  const Closure& c = evaluate(R"({"type": "lambert", "color": [0.8, 0.2, 0.1]})");
  expect_spectrum_eq(c.lobe(0).weight, RGBAlbedoSpectrum(rgb).sample(lambda));
  EXPECT_GT(c.lobe(0).weight[3], c.lobe(0).weight[0])
      << "a red albedo reflects more at 700 nm than at 400 nm";
}

TEST_F(GraphEval, ReflectanceAboveOneIsUnbounded) {
  const Closure& c = evaluate(R"({"type": "lambert", "color": [1.6, 0.4, 0.2]})");
  expect_spectrum_eq(c.lobe(0).weight, RGBUnboundedSpectrum({1.6f, 0.4f, 0.2f}).sample(lambda));
}

// {"wavelengths": [...], "values": [...]}: linear between the entries, clamped or zero outside.
TEST_F(GraphEval, InlineSpectrumTableIsLinearBetweenItsEntries) {
  const char* table =
      R"({"type": "lambert", "color": {"wavelengths": [400, 500, 600], "values": [0.2, 0.6, 0.4]%s}})";
  auto weight_at = [&](float nm, const char* extra) {
    lambda = SampledWavelengths::fixed(lanes({nm, nm, nm, nm}));
    char text[256];
    std::snprintf(text, sizeof text, table, extra);
    const Closure& c = evaluate(text);
    return c.lobe_count() > 0 ? c.lobe(0).weight[0] : 0.0f;  // a lobe of weight 0 is dropped
  };
  EXPECT_FLOAT_EQ(weight_at(450, ""), 0.4f);
  EXPECT_FLOAT_EQ(weight_at(550, ""), 0.5f);
  EXPECT_FLOAT_EQ(weight_at(650, ""), 0.4f);                      // clamped by default
  EXPECT_EQ(weight_at(650, R"(, "extrapolate": "zero")"), 0.0f);  // Mitsuba's spectra
  EXPECT_FLOAT_EQ(weight_at(500, R"(, "extrapolate": "zero")"), 0.6f);
}

TEST_F(GraphEval, MixWeightsTheTwoClosures) {
  const Closure& c = evaluate(R"({"nodes": {
      "a": {"type": "lambert", "color": 0.2},
      "b": {"type": "lambert", "color": [0.8, 0.2, 0.1]},
      "m": {"type": "mix", "a": {"link": "a"}, "b": {"link": "b"}, "factor": 0.25}}, "output": "m"})");
  ASSERT_EQ(c.lobe_count(), 2);
  const SampledSpectrum wa(0.2f), wb = RGBAlbedoSpectrum({0.8f, 0.2f, 0.1f}).sample(lambda);
  // The weights are summed over both lobes in either order.
  const SampledSpectrum total = c.lobe(0).weight + c.lobe(1).weight;
  expect_spectrum_eq(total, 0.75f * wa + 0.25f * wb, 1e-6f);
  const bool a_first = c.lobe(0).weight[0] == 0.75f * 0.2f;
  expect_spectrum_eq(c.lobe(a_first ? 0 : 1).weight, 0.75f * wa, 1e-6f);
  expect_spectrum_eq(c.lobe(a_first ? 1 : 0).weight, 0.25f * wb, 1e-6f);
}

TEST_F(GraphEval, MixWithLinkedFactorIsClamped) {
  textures = StubTextures();
  resolver.add_texture("mask.png", 1);
  ctx.uv = {1.7f, 0.0f};  // the stub texture returns u: a factor of 1.7 is clamped to 1
  const Closure& c = evaluate(R"({"nodes": {
      "t": {"type": "texture", "file": "mask.png"},
      "a": {"type": "lambert", "color": 0.2},
      "b": {"type": "lambert", "color": 0.6},
      "m": {"type": "mix", "a": {"link": "a"}, "b": {"link": "b"}, "factor": {"link": "t.value"}}}, "output": "m"})");
  ASSERT_EQ(c.lobe_count(), 1) << "the lobe of weight 0 is not added";
  expect_spectrum_eq(c.lobe(0).weight, SampledSpectrum(0.6f));
}

TEST_F(GraphEval, MultiplyScalesAClosure) {
  const Closure& c = evaluate(R"({"nodes": {
      "a": {"type": "lambert", "color": 0.3},
      "s": {"type": "multiply", "a": 2, "b": {"link": "a"}}}, "output": "s"})");
  ASSERT_EQ(c.lobe_count(), 1);
  expect_spectrum_eq(c.lobe(0).weight, SampledSpectrum(0.6f));
}

TEST_F(GraphEval, MultiplyByASpectrumScalesPerWavelength) {
  const Closure& c = evaluate(R"({"nodes": {
      "a": {"type": "lambert", "color": 0.5},
      "s": {"type": "multiply", "a": {"link": "a"}, "b": {"name": "A"}}}, "output": "s"})");
  expect_spectrum_eq(c.lobe(0).weight, 0.5f * named_spectrum("A")->sample(lambda), 1e-6f);
}

TEST_F(GraphEval, AddKeepsBothLobesAndTheirWeights) {
  const Closure& c = evaluate(R"({"nodes": {
      "a": {"type": "lambert", "color": 0.3},
      "b": {"type": "lambert", "color": 0.4},
      "s": {"type": "add", "a": {"link": "a"}, "b": {"link": "b"}}}, "output": "s"})");
  ASSERT_EQ(c.lobe_count(), 2);
  EXPECT_FLOAT_EQ(c.lobe(0).weight[0] + c.lobe(1).weight[0], 0.7f);
  EXPECT_EQ(std::min(c.lobe(0).weight[2], c.lobe(1).weight[2]), 0.3f);
}

TEST_F(GraphEval, ClosureUsedTwiceGetsTheSumOfItsWeights) {
  const Closure& c = evaluate(R"({"nodes": {
      "a": {"type": "lambert", "color": 0.25},
      "s": {"type": "add", "a": {"link": "a"}, "b": {"link": "a"}}}, "output": "s"})");
  ASSERT_EQ(c.lobe_count(), 1);
  expect_spectrum_eq(c.lobe(0).weight, SampledSpectrum(0.5f));
}

TEST_F(GraphEval, EmissionIsStrengthTimesNormalizedD65) {
  const SampledSpectrum d65_radiance = 3.0f * d65()->sample(lambda);
  const Closure& c = evaluate(R"({"type": "emission", "strength": 3})");
  EXPECT_EQ(c.lobe_count(), 0);
  expect_spectrum_eq(c.emission(), d65_radiance, 1e-6f);
  expect_spectrum_eq(evaluate(R"({"type": "emission", "color": {"name": "D65"}, "strength": 3})").emission(),
                     d65_radiance, 1e-6f);
  // D65 at luminance 1: a strength of 3 has luminance 3.
  EXPECT_NEAR(spectrum_to_xyz(*d65()).y, 1.0f, 1e-3f);
}

TEST_F(GraphEval, EmissionColourIsAnIlluminant) {
  const Closure& c = evaluate(R"({"type": "emission", "color": [0.9, 0.5, 0.2], "strength": 2})");
  expect_spectrum_eq(c.emission(), 2.0f * RGBIlluminantSpectrum({0.9f, 0.5f, 0.2f}).sample(lambda), 1e-6f);
}

TEST_F(GraphEval, EmissionAndLobesAddUp) {
  const Closure& c = evaluate(R"({"nodes": {
      "d": {"type": "lambert", "color": 0.5},
      "e": {"type": "emission", "strength": 2},
      "s": {"type": "add", "a": {"link": "d"}, "b": {"link": "e"}},
      "h": {"type": "multiply", "a": {"link": "s"}, "b": 0.5}}, "output": "h"})");
  ASSERT_EQ(c.lobe_count(), 1) << material->listing();
  expect_spectrum_eq(c.lobe(0).weight, SampledSpectrum(0.25f));
  expect_spectrum_eq(c.emission(), d65()->sample(lambda), 1e-6f);
}

TEST_F(GraphEval, NestedClosureAlgebra) {
  // mix(2 a, b + e, 0.25) = 1.5 a + 0.25 b + 0.25 e.
  const Closure& c = evaluate(R"({"nodes": {
      "a": {"type": "lambert", "color": 0.2},
      "b": {"type": "lambert", "color": 0.6},
      "e": {"type": "emission", "strength": 4},
      "twice": {"type": "multiply", "a": {"link": "a"}, "b": 2},
      "sum": {"type": "add", "a": {"link": "b"}, "b": {"link": "e"}},
      "m": {"type": "mix", "a": {"link": "twice"}, "b": {"link": "sum"}, "factor": 0.25}}, "output": "m"})");
  ASSERT_EQ(c.lobe_count(), 2) << material->listing();
  const float w0 = c.lobe(0).weight[0], w1 = c.lobe(1).weight[0];
  EXPECT_FLOAT_EQ(std::max(w0, w1), 1.5f * 0.2f);
  EXPECT_FLOAT_EQ(std::min(w0, w1), 0.25f * 0.6f);
  expect_spectrum_eq(c.emission(), d65()->sample(lambda), 1e-6f);
}

TEST_F(GraphEval, TextureLookupUsesTheMeshUv) {
  resolver.add_texture("rock.jpg", 3);
  ctx.uv = {0.6f, 0.3f};
  ctx.uv_footprint = 0.01f;
  const Closure& c = evaluate(R"({"nodes": {
      "t": {"type": "texture", "file": "rock.jpg", "colorspace": "srgb"},
      "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"})");
  EXPECT_EQ(resolver.colorspaces, std::vector<std::string>{"srgb"});
  EXPECT_EQ(textures.last_uv.x, 0.6f);
  EXPECT_EQ(textures.last_uv.y, 0.3f);
  EXPECT_EQ(textures.last_footprint, 0.01f);
  // The stub texture holds (u, v, 0.25); a varying colour is upsampled per evaluation.
  expect_spectrum_eq(c.lobe(0).weight, RGBAlbedoSpectrum({0.6f, 0.3f, 0.25f}).sample(lambda), 1e-6f);
}

TEST_F(GraphEval, TextureUvInputFlowsThroughMath) {
  resolver.add_texture("rock.jpg", 3);
  ctx.uv = {0.2f, 0.1f};
  evaluate(R"({"nodes": {
      "uv": {"type": "uv"},
      "tiled": {"type": "multiply", "a": {"link": "uv"}, "b": 4},
      "t": {"type": "texture", "file": "rock.jpg", "uv": {"link": "tiled"}},
      "d": {"type": "lambert", "color": {"link": "t"}}}, "output": "d"})");
  EXPECT_FLOAT_EQ(textures.last_uv.x, 0.8f);
  EXPECT_FLOAT_EQ(textures.last_uv.y, 0.4f);
}

TEST_F(GraphEval, TextureValueOutputReadsItsChannel) {
  resolver.add_texture("rgba.exr", 4);
  const Closure& c = evaluate(R"({"nodes": {
      "t": {"type": "texture", "file": "rgba.exr", "channel": 3},
      "e": {"type": "emission", "color": 1, "strength": {"link": "t.value"}}}, "output": "e"})");
  EXPECT_EQ(textures.last_first_channel, 3);
  EXPECT_EQ(textures.lookups, 1) << "the unused colour output is not looked up";
  expect_spectrum_eq(c.emission(), SampledSpectrum(0.1f * 3), 1e-6f);
}

TEST_F(GraphEval, VertexColourNode) {
  ctx.vertex_colour = {0.1f, 0.7f, 0.3f};
  const Closure& c = evaluate(R"({"nodes": {
      "vc": {"type": "vertex_colour"},
      "d": {"type": "lambert", "color": {"link": "vc"}}}, "output": "d"})");
  expect_spectrum_eq(c.lobe(0).weight, RGBAlbedoSpectrum({0.1f, 0.7f, 0.3f}).sample(lambda), 1e-6f);
  expect_spectrum_eq(c.lobe(0).weight, upsample_reflectance({0.1f, 0.7f, 0.3f}, lambda));
}

TEST_F(GraphEval, VaryingColourIntoEmissionIsUpsampledAsIlluminant) {
  ctx.vertex_colour = {0.9f, 0.4f, 0.2f};
  const Closure& c = evaluate(R"({"nodes": {
      "vc": {"type": "vertex_colour"},
      "e": {"type": "emission", "color": {"link": "vc"}}}, "output": "e"})");
  expect_spectrum_eq(c.emission(), RGBIlluminantSpectrum({0.9f, 0.4f, 0.2f}).sample(lambda), 1e-5f);
}

TEST_F(GraphEval, ColourTimesSpectrumIsATint) {
  // A colour multiplied with a spectrum is a dimensionless tint, even on the way to an emission.
  ctx.vertex_colour = {0.9f, 0.4f, 0.2f};
  const Closure& c = evaluate(R"({"nodes": {
      "vc": {"type": "vertex_colour"},
      "x": {"type": "multiply", "a": {"link": "vc"}, "b": {"name": "A"}},
      "e": {"type": "emission", "color": {"link": "x"}}}, "output": "e"})");
  expect_spectrum_eq(
      c.emission(),
      RGBAlbedoSpectrum({0.9f, 0.4f, 0.2f}).sample(lambda) * named_spectrum("A")->sample(lambda), 1e-5f);
}

TEST_F(GraphEval, ColourAddedToASpectrumTakesTheRoleOfTheResult) {
  ctx.vertex_colour = {0.9f, 0.4f, 0.2f};
  const Closure& c = evaluate(R"({"nodes": {
      "vc": {"type": "vertex_colour"},
      "x": {"type": "add", "a": {"link": "vc"}, "b": {"name": "A"}},
      "y": {"type": "multiply", "a": {"link": "x"}, "b": 2},
      "e": {"type": "emission", "color": {"link": "y"}}}, "output": "e"})");
  const SampledSpectrum expected =
      2.0f * (RGBIlluminantSpectrum({0.9f, 0.4f, 0.2f}).sample(lambda) + named_spectrum("A")->sample(lambda));
  expect_spectrum_eq(c.emission(), expected, 1e-5f);
}

TEST_F(GraphEval, RgbToSpectrumModes) {
  const Closure& c = evaluate(R"({"nodes": {
      "r": {"type": "rgb_to_spectrum", "color": [0.2, 0.5, 0.9], "mode": "illuminant"},
      "e": {"type": "emission", "color": {"link": "r"}}}, "output": "e"})");
  expect_spectrum_eq(c.emission(), RGBIlluminantSpectrum({0.2f, 0.5f, 0.9f}).sample(lambda), 1e-6f);
  ctx.vertex_colour = {0.2f, 0.5f, 0.9f};
  const Closure& d = evaluate(R"({"nodes": {
      "vc": {"type": "vertex_colour"},
      "r": {"type": "rgb_to_spectrum", "color": {"link": "vc"}},
      "e": {"type": "emission", "color": {"link": "r"}}}, "output": "e"})");
  expect_spectrum_eq(d.emission(), RGBAlbedoSpectrum({0.2f, 0.5f, 0.9f}).sample(lambda), 1e-6f);
}

TEST_F(GraphEval, SpectrumFromCsvFile) {
  std::ofstream(resolver.resolve("red.csv")) << "# test reflectance\nnm,r\n400,0.1\n550,0.2\n700,0.9\n";
  const Closure& c = evaluate(R"({"nodes": {
      "refl": {"type": "spectrum", "file": "red.csv", "scale": 0.5},
      "d": {"type": "lambert", "color": {"link": "refl"}}}, "output": "d"})");
  // Linear between the entries, clamped beyond the last one.
  expect_spectrum_eq(c.lobe(0).weight,
                     0.5f * lanes({0.1f, 0.1f + 0.1f * 100.0f / 150.0f, 0.2f + 0.7f / 3.0f, 0.9f}), 1e-5f);
  const Closure& d = evaluate(R"({"type": "lambert", "color": {"file": "red.csv"}})");
  EXPECT_FLOAT_EQ(d.lobe(0).weight[0], 0.1f);
}

// A table over 450-650 nm seen at 400, 500, 600 and 700 nm: the outer two are outside it.
TEST_F(GraphEval, SpectrumFileExtrapolation) {
  std::ofstream(resolver.resolve("lamp.csv")) << "nm,e\n450,2\n550,4\n650,6\n";
  const SampledSpectrum held = lanes({2.0f, 3.0f, 5.0f, 6.0f}), zero = lanes({0.0f, 3.0f, 5.0f, 0.0f});
  for (const char* node : {R"({"type": "spectrum", "file": "lamp.csv"})",
                           R"({"type": "spectrum", "file": "lamp.csv", "extrapolate": "clamp"})"}) {
    const Closure& c = evaluate(R"({"nodes": {"s": )" + std::string(node) +
                                R"(, "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})");
    expect_spectrum_eq(c.emission(), held, 1e-6f);
  }
  const Closure& node = evaluate(R"({"nodes": {
      "s": {"type": "spectrum", "file": "lamp.csv", "extrapolate": "zero"},
      "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})");
  expect_spectrum_eq(node.emission(), zero, 1e-6f);
  // The same choice on a spectrum literal.
  const Closure& literal =
      evaluate(R"({"type": "emission", "color": {"file": "lamp.csv", "extrapolate": "zero", "scale": 2}})");
  expect_spectrum_eq(literal.emission(), 2.0f * zero, 1e-6f);
  expect_spectrum_eq(evaluate(R"({"type": "emission", "color": {"file": "lamp.csv"}})").emission(), held,
                     1e-6f);
}

TEST_F(GraphEval, ExampleGraphFromTheDocs) {
  std::ofstream(resolver.resolve("red.csv")) << "nm,r\n360,0.5\n830,0.5\n";
  resolver.add_texture("rock.jpg", 3);
  ctx.uv = {0.5f, 0.5f};
  const Closure& c = evaluate(R"({
      "nodes": {
        "refl": {"type": "spectrum", "file": "red.csv"},
        "tex":  {"type": "texture", "file": "rock.jpg", "colorspace": "srgb"},
        "tint": {"type": "multiply", "a": {"link": "refl"}, "b": {"link": "tex.color"}},
        "diffuse": {"type": "lambert", "color": {"link": "tint"}},
        "glow": {"type": "emission", "color": {"name": "D65"}, "strength": 5},
        "out": {"type": "add", "a": {"link": "diffuse"}, "b": {"link": "glow"}}
      },
      "output": "out"})");
  ASSERT_EQ(c.lobe_count(), 1);
  expect_spectrum_eq(c.lobe(0).weight, 0.5f * upsample_reflectance({0.5f, 0.5f, 0.25f}, lambda), 1e-6f);
  expect_spectrum_eq(c.emission(), 5.0f * named_spectrum("D65")->sample(lambda), 1e-6f);
}

TEST_F(GraphEval, RepeatedEvaluationIsIdentical) {
  resolver.add_texture("rock.jpg", 3);
  material = compile(R"({"nodes": {
      "t": {"type": "texture", "file": "rock.jpg"},
      "d": {"type": "lambert", "color": {"link": "t"}},
      "e": {"type": "emission", "color": {"link": "t"}, "strength": 0.5},
      "m": {"type": "mix", "a": {"link": "d"}, "b": {"link": "e"}, "factor": 0.3}}, "output": "m"})",
                     resolver);
  ctx.uv = {0.3f, 0.9f};
  const Closure first = evaluate(*material);
  ctx.uv = {0.9f, 0.1f};
  evaluate(*material);
  ctx.uv = {0.3f, 0.9f};
  const Closure& again = evaluate(*material);
  ASSERT_EQ(again.lobe_count(), first.lobe_count());
  expect_spectrum_eq(again.lobe(0).weight, first.lobe(0).weight);
  expect_spectrum_eq(again.emission(), first.emission());
}

TEST_F(GraphEval, MissingWavelengthsIsAnError) {
  material = compile(R"({"type": "lambert"})");
  ShadingContext no_lambda;
  EXPECT_THROW(material->evaluate(no_lambda, arena, closure), std::invalid_argument);
}

}  // namespace
}  // namespace ochre::test::graph_eval_test
