// What compilation does to a graph: constant folding, dead-node removal, the material facts, and
// extension through the node registry.

#include <gtest/gtest.h>

#include "materials/lobes/lambert.h"
#include "materials/material_test_support.h"
#include "materials/nodes/node_registry.h"

namespace ochre::test::graph_compile_test {
namespace {

bool lists(const CompiledMaterial& m, const std::string& fragment) {
  return m.listing().find(fragment) != std::string::npos;
}

TEST(ConstantFolding, MultiplyOfConstantsFoldsToAConstant) {
  const auto m = compile(R"({"nodes": {
      "a": {"type": "constant", "value": 0.5},
      "b": {"type": "constant", "value": 0.4},
      "x": {"type": "multiply", "a": {"link": "a"}, "b": {"link": "b"}},
      "d": {"type": "lambert", "color": {"link": "x"}}}, "output": "d"})");
  EXPECT_EQ(m->instruction_count(), 1) << m->listing();
  EXPECT_FALSE(lists(*m, "multiply")) << m->listing();
  EXPECT_EQ(m->facts().nodes_declared, 4);
  EXPECT_EQ(m->facts().nodes_compiled, 1);

  LobeArena arena;
  Closure c;
  ShadingContext ctx;
  ctx.lambda = &test_wavelengths();
  m->evaluate(ctx, arena, c);
  EXPECT_EQ(c.lobe(0).weight, SampledSpectrum(0.5f * 0.4f));
}

TEST(ConstantFolding, ColourMathFoldsAndConstantColourIsPreBuilt) {
  // [0.5, 0.2, 0.1] * 2 + 0.1 folds to one colour; its spectrum is built at compile time and only
  // sampled per evaluation (no table lookup, no conversion instruction).
  const auto m = compile(R"({"nodes": {
      "x": {"type": "multiply", "a": [0.25, 0.1, 0.05], "b": 2},
      "y": {"type": "add", "a": {"link": "x"}, "b": 0.1},
      "d": {"type": "lambert", "color": {"link": "y"}}}, "output": "d"})");
  EXPECT_EQ(m->facts().nodes_compiled, 1);
  EXPECT_FALSE(lists(*m, "convert")) << m->listing();
  EXPECT_TRUE(lists(*m, "sample spectrum")) << m->listing();
  EXPECT_EQ(m->instruction_count(), 2) << m->listing();
}

TEST(ConstantFolding, ConstantSpectraMultiplyIntoOneSpectrum) {
  const auto m = compile(R"({"nodes": {
      "x": {"type": "multiply", "a": {"name": "D65"}, "b": [0.9, 0.5, 0.2]},
      "e": {"type": "emission", "color": {"link": "x"}, "strength": 2}}, "output": "e"})");
  EXPECT_EQ(m->facts().nodes_compiled, 1);
  EXPECT_EQ(m->instruction_count(), 2) << m->listing();  // sample the product, emit
}

TEST(ConstantFolding, IdentityOperationsAreBypassed) {
  const auto m = compile(R"({"nodes": {
      "vc": {"type": "vertex_colour"},
      "x": {"type": "multiply", "a": {"link": "vc"}, "b": 1},
      "y": {"type": "add", "a": 0, "b": {"link": "x"}},
      "d": {"type": "lambert", "color": {"link": "y"}}}, "output": "d"})");
  EXPECT_FALSE(lists(*m, "multiply")) << m->listing();
  EXPECT_FALSE(lists(*m, "add")) << m->listing();
  EXPECT_EQ(m->facts().nodes_compiled, 2);  // vertex_colour and lambert
}

TEST(DeadNodes, UnreachableNodesAreDropped) {
  StubResolver resolver;
  resolver.add_texture("rock.jpg", 3);
  const auto m = compile(R"({"nodes": {
      "unused_tex": {"type": "texture", "file": "rock.jpg"},
      "unused_vc": {"type": "vertex_colour"},
      "d": {"type": "lambert", "color": 0.5}}, "output": "d"})",
                         resolver);
  EXPECT_EQ(m->facts().nodes_declared, 3);
  EXPECT_EQ(m->facts().nodes_compiled, 1);
  EXPECT_LT(m->facts().nodes_compiled, m->facts().nodes_declared);
  EXPECT_FALSE(m->facts().needs_uv);
  EXPECT_FALSE(m->facts().needs_vertex_colour);
}

TEST(DeadNodes, MixWithConstantFactorDropsTheOtherBranch) {
  const auto m = compile(R"({"nodes": {
      "d": {"type": "lambert", "color": 0.5},
      "e": {"type": "emission", "strength": 4},
      "m": {"type": "mix", "a": {"link": "d"}, "b": {"link": "e"}, "factor": 0}}, "output": "m"})");
  EXPECT_EQ(m->facts().nodes_compiled, 1);
  EXPECT_FALSE(m->facts().is_emissive);
  EXPECT_TRUE(m->facts().has_lobes);
}

TEST(Facts, Lambert) {
  const MaterialFacts f = compile(R"({"type": "lambert", "color": 0.5})")->facts();
  EXPECT_TRUE(f.has_lobes);
  EXPECT_FALSE(f.is_emissive);
  EXPECT_FALSE(f.polarizes);
  EXPECT_FALSE(f.has_delta_lobes);
  EXPECT_FALSE(f.needs_uv);
  EXPECT_FALSE(f.needs_vertex_colour);
  EXPECT_FALSE(f.spectrally_varying);
  EXPECT_TRUE(f.uniform_over_surface);
  EXPECT_EQ(f.nodes_declared, 1);
  EXPECT_EQ(f.nodes_compiled, 1);
}

TEST(Facts, BlackLambertHasNoLobes) {
  EXPECT_FALSE(compile(R"({"type": "lambert", "color": [0, 0, 0]})")->facts().has_lobes);
}

TEST(Facts, SpectrallyVarying) {
  EXPECT_FALSE(compile(R"({"type": "lambert", "color": [0.4, 0.4, 0.4]})")->facts().spectrally_varying);
  EXPECT_TRUE(compile(R"({"type": "lambert", "color": [0.8, 0.2, 0.1]})")->facts().spectrally_varying);
  EXPECT_TRUE(compile(R"({"type": "emission"})")->facts().spectrally_varying) << "D65 varies";
  EXPECT_TRUE(compile(R"({"nodes": {"vc": {"type": "vertex_colour"},
                                    "d": {"type": "lambert", "color": {"link": "vc"}}}, "output": "d"})")
                  ->facts()
                  .spectrally_varying);
  // A varying float scaling a flat spectrum stays flat.
  StubResolver resolver;
  resolver.add_texture("mask.png", 1);
  EXPECT_FALSE(compile(R"({"nodes": {"t": {"type": "texture", "file": "mask.png"},
                                     "x": {"type": "multiply", "a": {"link": "t.value"}, "b": 0.5},
                                     "d": {"type": "lambert", "color": {"link": "x"}}}, "output": "d"})",
                       resolver)
                   ->facts()
                   .spectrally_varying);
}

TEST(Facts, Emission) {
  EXPECT_TRUE(compile(R"({"type": "emission", "strength": 2})")->facts().is_emissive);
  EXPECT_FALSE(compile(R"({"type": "emission", "strength": 2})")->facts().has_lobes);
  EXPECT_FALSE(compile(R"({"type": "emission", "strength": 0})")->facts().is_emissive);
  EXPECT_FALSE(compile(R"({"type": "emission", "color": 0})")->facts().is_emissive);
  StubResolver resolver;
  resolver.add_texture("mask.png", 1);
  EXPECT_TRUE(compile(R"({"nodes": {"t": {"type": "texture", "file": "mask.png"},
                                    "e": {"type": "emission", "strength": {"link": "t.value"}}}, "output": "e"})",
                      resolver)
                  ->facts()
                  .is_emissive);
}

TEST(Facts, TexturesAndVertexColours) {
  StubResolver resolver;
  resolver.add_texture("rock.jpg", 3);
  const MaterialFacts t = compile(R"({"nodes": {"t": {"type": "texture", "file": "rock.jpg"},
                                                "d": {"type": "lambert", "color": {"link": "t"}}}, "output": "d"})",
                                  resolver)
                              ->facts();
  EXPECT_TRUE(t.needs_uv);
  EXPECT_FALSE(t.needs_vertex_colour);
  EXPECT_FALSE(t.uniform_over_surface);
  const MaterialFacts v = compile(R"({"nodes": {"v": {"type": "vertex_colour"},
                                                "d": {"type": "lambert", "color": {"link": "v"}}}, "output": "d"})")
                              ->facts();
  EXPECT_FALSE(v.needs_uv);
  EXPECT_TRUE(v.needs_vertex_colour);
  EXPECT_FALSE(v.uniform_over_surface);
  const MaterialFacts u = compile(R"({"nodes": {"u": {"type": "uv"},
                                                "x": {"type": "multiply", "a": {"link": "u"}, "b": 0},
                                                "d": {"type": "lambert", "color": 0.5}}, "output": "d"})")
                              ->facts();
  EXPECT_FALSE(u.needs_uv) << "the uv node is dead";
  EXPECT_TRUE(u.uniform_over_surface) << "the uv node is dead";
}

// Gated value instructions (docs/nodes.md, "Program"): skipped while the one float every use multiplies
// them by is 0. True when the listing's line of `label` says so.
bool gated(const CompiledMaterial& m, const std::string& label) {
  const std::string text = m.listing();
  const size_t at = text.find(label + "  in[");
  if (at == std::string::npos) ADD_FAILURE() << "no instruction " << label << " in\n" << text;
  const std::string line = at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
  return line.find("skipped while") != std::string::npos;
}

std::string mask_material(const std::string& extra_nodes, const std::string& factor) {
  return R"({"nodes": {
      "f": {"type": "projection", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]},
      "t": {"type": "texture", "file": "mask.png", "uv": {"link": "f.uv"}},
      "cover": {"type": "multiply", "a": {"link": "t.value"}, "b": )" +
         factor + R"(},)" + extra_nodes + R"(
      "d": {"type": "lambert", "color": {"link": "cover"}}}, "output": "d"})";
}

TEST(Gates, AValueOnlyMultipliedByOneComputedFloatIsGatedByIt) {
  StubResolver resolver;
  resolver.add_texture("mask.png", 1);
  const auto mask = compile(mask_material("", R"({"link": "f.inside"})"), resolver);
  EXPECT_TRUE(gated(*mask, "texture 't'")) << mask->listing();
  EXPECT_TRUE(lists(*mask, "skipped while [6] = 0")) << "by the projection's inside: " << mask->listing();
  // A colour times the float (the float converted to a colour for the product) is gated too.
  const auto colour = compile(R"({"nodes": {
      "f": {"type": "projection", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]},
      "t": {"type": "texture", "file": "mask.png", "uv": {"link": "f.uv"}},
      "tint": {"type": "multiply", "a": {"link": "t.color"}, "b": {"link": "f.inside"}},
      "d": {"type": "lambert", "color": {"link": "tint"}}}, "output": "d"})",
                              resolver);
  EXPECT_TRUE(gated(*colour, "texture 't'")) << colour->listing();
}

TEST(Gates, NotGatedWhenAnotherUseNeedsTheValue) {
  StubResolver resolver;
  resolver.add_texture("mask.png", 1);
  // The texture also feeds a lambert directly.
  const auto shared = compile(R"({"nodes": {
      "f": {"type": "projection", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]},
      "t": {"type": "texture", "file": "mask.png", "uv": {"link": "f.uv"}},
      "cover": {"type": "multiply", "a": {"link": "t.value"}, "b": {"link": "f.inside"}},
      "d": {"type": "lambert", "color": {"link": "cover"}},
      "e": {"type": "lambert", "color": {"link": "t.value"}},
      "out": {"type": "add", "a": {"link": "d"}, "b": {"link": "e"}}}, "output": "out"})",
                              resolver);
  EXPECT_FALSE(gated(*shared, "texture 't'")) << shared->listing();
  // Multiplied by two different floats.
  const auto two = compile(R"({"nodes": {
      "f": {"type": "projection", "origin": [0, 0, 0], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]},
      "g": {"type": "projection", "origin": [0, 0, 0], "u_axis": [2, 0, 0], "v_axis": [0, 2, 0]},
      "t": {"type": "texture", "file": "mask.png", "uv": {"link": "f.uv"}},
      "a": {"type": "multiply", "a": {"link": "t.value"}, "b": {"link": "f.inside"}},
      "b": {"type": "multiply", "a": {"link": "t.value"}, "b": {"link": "g.inside"}},
      "s": {"type": "add", "a": {"link": "a"}, "b": {"link": "b"}},
      "d": {"type": "lambert", "color": {"link": "s"}}}, "output": "d"})",
                           resolver);
  EXPECT_FALSE(gated(*two, "texture 't'")) << two->listing();
  // ... while g, whose one used output is multiplied by the texture's value computed before it, is.
  EXPECT_TRUE(gated(*two, "projection 'g'")) << two->listing();
  // The factor is computed from the value itself, so it is not known before it.
  const auto self = compile(mask_material(R"(
      "twice": {"type": "multiply", "a": {"link": "t.value"}, "b": 2},)",
                                          R"({"link": "twice"})"),
                            resolver);
  EXPECT_FALSE(gated(*self, "texture 't'")) << self->listing();
  EXPECT_TRUE(gated(*self, "multiply 'twice'")) << "its one use is a product with the texture's value";
  // A float scaling a closure: the closure's weight is known only after every value instruction.
  const auto scale = compile(R"({"nodes": {
      "t": {"type": "texture", "file": "mask.png"},
      "d": {"type": "lambert", "color": 0.5},
      "s": {"type": "multiply", "a": {"link": "d"}, "b": {"link": "t.value"}}}, "output": "s"})",
                             resolver);
  EXPECT_FALSE(gated(*scale, "texture 't'")) << scale->listing();
}

// A closure added through the registry changes the facts through its lobe flags alone.
NodeRegistry registry_with_polarizer() {
  NodeRegistry r;
  for (const auto& def : NodeRegistry::builtin().definitions()) r.add(*def);
  NodeDefinition d;
  d.name = "test_polarizer";
  d.outputs = {{"closure", SocketType::kClosure, false, ""}};
  d.eval = [](const NodeArgs&) {};
  d.closure_traits = [](std::span<const InputView>, const void*) {
    return ClosureTraits{kLobeReflection | kLobeDelta | kLobePolarizing, false};
  };
  r.add(d);
  return r;
}

TEST(Registry, NewClosureNodeDrivesTheFacts) {
  const NodeRegistry registry = registry_with_polarizer();
  StubResolver resolver;
  const auto m = compile_material(nlohmann::json::parse(R"({"nodes": {
      "p": {"type": "test_polarizer"}, "d": {"type": "lambert"},
      "s": {"type": "add", "a": {"link": "p"}, "b": {"link": "d"}}}, "output": "s"})"),
                                  "m", kSceneFile, resolver, registry);
  EXPECT_TRUE(m->facts().polarizes);
  EXPECT_TRUE(m->facts().has_delta_lobes);
  EXPECT_TRUE(m->facts().has_lobes);
}

TEST(Registry, BuiltinNodesAreRegistered) {
  const std::vector<std::string> names = NodeRegistry::builtin().names();
  for (const char* n : {"add", "constant", "emission", "lambert", "mix", "multiply", "rgb_to_spectrum",
                        "spectrum", "texture", "uv", "vertex_colour"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

TEST(Registry, RejectsDuplicatesAndIncompleteDefinitions) {
  NodeRegistry r;
  NodeDefinition d;
  d.name = "x";
  d.outputs = {{"value", SocketType::kFloat, false, ""}};
  EXPECT_THROW(r.add(d), std::logic_error) << "no eval function";
  d.eval = [](const NodeArgs&) {};
  r.add(d);
  EXPECT_THROW(r.add(d), std::logic_error);
}

}  // namespace
}  // namespace ochre::test::graph_compile_test
