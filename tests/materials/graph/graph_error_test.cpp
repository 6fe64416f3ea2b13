// Every way the material compiler rejects a graph: a GraphError naming file, material, node and
// parameter, with a message that says what is wrong.

#include "materials/graph/graph_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "materials/material_test_support.h"
#include "support/test_paths.h"

namespace ochre::test::graph_error_test {
namespace {

using nlohmann::json;

GraphError error_of(const json& material, StubResolver& resolver) {
  try {
    compile_material(material, "m", kSceneFile, resolver);
  } catch (const GraphError& e) {
    return e;
  }
  ADD_FAILURE() << "no GraphError for " << material.dump();
  return GraphError("", "", "", "", "");
}

GraphError error_of(const std::string& text) {
  StubResolver resolver;
  return error_of(json::parse(text), resolver);
}

// The error names this node and parameter, and the message says so along with `fragment`.
void expect_error_at(const GraphError& e, const std::string& node, const std::string& parameter,
                     const std::string& fragment) {
  SCOPED_TRACE(e.what());
  const std::string message = e.what();
  EXPECT_EQ(e.file(), kSceneFile);
  EXPECT_EQ(e.material(), "m");
  EXPECT_EQ(e.node(), node);
  EXPECT_EQ(e.parameter(), parameter);
  EXPECT_EQ(message.rfind("scene.json: material 'm'", 0), 0u);
  if (!node.empty()) {
    EXPECT_NE(message.find("node '" + node + "'"), std::string::npos);
  }
  if (!parameter.empty()) {
    EXPECT_NE(message.find("parameter '" + parameter + "'"), std::string::npos);
  }
  EXPECT_NE(message.find(fragment), std::string::npos) << "missing: " << fragment;
}

TEST(GraphError, MessageFormatLeavesOutEmptyParts) {
  EXPECT_STREQ(GraphError("s.json", "wall", "tex", "file", "gone").what(),
               "s.json: material 'wall', node 'tex', parameter 'file': gone");
  EXPECT_STREQ(GraphError("s.json", "wall", "", "color", "bad").what(),
               "s.json: material 'wall', parameter 'color': bad");
  EXPECT_STREQ(GraphError("s.json", "", "", "", "bad").what(), "s.json: bad");
  EXPECT_STREQ(GraphError("", "", "", "", "bad").what(), "bad");
  EXPECT_EQ(GraphError("s.json", "wall", "tex", "file", "gone").reason(), "gone");
}

TEST(GraphErrors, MaterialNotAnObject) {
  expect_error_at(error_of("[1, 2]"), "", "", "must be a JSON object");
  expect_error_at(error_of("{\"color\": 0.5}"), "", "", "needs \"type\"");
}

TEST(GraphErrors, NodeNotAnObject) {
  expect_error_at(error_of(R"({"nodes": {"a": 3}, "output": "a"})"), "a", "", "must be a JSON object");
}

TEST(GraphErrors, MissingType) {
  expect_error_at(error_of(R"({"nodes": {"a": {"color": 1}}, "output": "a"})"), "a", "type",
                  "missing node type");
}

TEST(GraphErrors, UnknownTypeListsKnownTypes) {
  const GraphError e = error_of(R"({"nodes": {"a": {"type": "lambertian"}}, "output": "a"})");
  expect_error_at(e, "a", "type", "unknown node type 'lambertian'");
  for (const char* known : {"lambert", "emission", "texture", "mix", "spectrum"})
    EXPECT_NE(std::string(e.what()).find(known), std::string::npos) << known;
}

TEST(GraphErrors, UnknownParameterListsTheNodesParameters) {
  const GraphError e =
      error_of(R"({"nodes": {"t": {"type": "texture", "file": "a.png", "colour_space": "srgb"},
                                              "d": {"type": "lambert", "color": {"link": "t"}}}, "output": "d"})");
  expect_error_at(e, "t", "colour_space", "unknown parameter");
  for (const char* p : {"uv", "file", "colorspace", "channel"})
    EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << p;
  // The one-node shorthand has no node name.
  expect_error_at(error_of(R"({"type": "lambert", "albedo": 0.5})"), "", "albedo", "it takes: color");
}

TEST(GraphErrors, ClosureIntoColourSocket) {
  expect_error_at(error_of(R"({"nodes": {"d": {"type": "lambert"},
                                         "r": {"type": "rgb_to_spectrum", "color": {"link": "d"}},
                                         "out": {"type": "lambert", "color": {"link": "r"}}}, "output": "out"})"),
                  "r", "color", "type mismatch: 'd.closure' is a closure, this input takes a colour");
}

TEST(GraphErrors, ColourIntoFloatSocket) {
  StubResolver resolver;
  resolver.add_texture("a.png", 3);
  const json m = json::parse(R"({"nodes": {"t": {"type": "texture", "file": "a.png"},
                                           "e": {"type": "emission", "strength": {"link": "t.color"}}},
                                 "output": "e"})");
  expect_error_at(error_of(m, resolver), "e", "strength", "'t.color' is a colour, this input takes a float");
  expect_error_at(error_of(R"({"type": "emission", "strength": [1, 2, 3]})"), "", "strength",
                  "type mismatch: the constant [1, 2, 3] is a colour");
}

TEST(GraphErrors, VectorAndColourDoNotConvert) {
  expect_error_at(error_of(R"({"type": "lambert", "color": {"vector": [0.1, 0.2, 0.3]}})"), "", "color",
                  "vectors and colours do not convert");
  expect_error_at(error_of(R"({"nodes": {"u": {"type": "uv"},
                                         "x": {"type": "add", "a": {"link": "u"}, "b": [1, 1, 1]},
                                         "d": {"type": "lambert", "color": {"link": "x"}}}, "output": "d"})"),
                  "x", "b", "a vector cannot be combined with a colour");
}

TEST(GraphErrors, ClosureTimesClosure) {
  expect_error_at(error_of(R"({"nodes": {"a": {"type": "lambert"}, "b": {"type": "lambert"},
                                         "x": {"type": "multiply", "a": {"link": "a"}, "b": {"link": "b"}}},
                               "output": "x"})"),
                  "x", "b", "closure x closure");
}

TEST(GraphErrors, ClosurePlusValue) {
  expect_error_at(error_of(R"({"nodes": {"a": {"type": "lambert"},
                                         "x": {"type": "add", "a": {"link": "a"}, "b": 0.5}}, "output": "x"})"),
                  "x", "b", "cannot add a closure and a float");
}

TEST(GraphErrors, LinkToUnknownNodeOrOutput) {
  expect_error_at(
      error_of(R"({"nodes": {"d": {"type": "lambert", "color": {"link": "refl"}}}, "output": "d"})"), "d",
      "color", "link to unknown node 'refl' (nodes: d)");
  expect_error_at(error_of(R"({"nodes": {"c": {"type": "constant", "value": 0.5},
                                         "d": {"type": "lambert", "color": {"link": "c.colour"}}}, "output": "d"})"),
                  "d", "color", "node 'c' has no output 'colour' (outputs: value)");
}

TEST(GraphErrors, CycleNamesItsNodes) {
  const GraphError e = error_of(R"({"nodes": {
      "a": {"type": "add", "a": {"link": "b"}, "b": 0.1},
      "b": {"type": "multiply", "a": {"link": "c"}, "b": 0.5},
      "c": {"type": "mix", "a": {"link": "a"}, "b": 0.2},
      "d": {"type": "lambert", "color": {"link": "a"}}}, "output": "d"})");
  EXPECT_NE(e.reason().find("cycle"), std::string::npos) << e.what();
  for (const char* node : {"'a'", "'b'", "'c'"}) EXPECT_NE(e.reason().find(node), std::string::npos) << node;
  EXPECT_EQ(e.reason().find("'d'"), std::string::npos) << "d is not on the cycle";
  EXPECT_FALSE(e.node().empty());
  EXPECT_FALSE(e.parameter().empty());
}

TEST(GraphErrors, SelfLinkIsACycle) {
  expect_error_at(error_of(R"({"nodes": {"a": {"type": "add", "a": {"link": "a"}},
                                         "d": {"type": "lambert", "color": {"link": "a"}}}, "output": "d"})"),
                  "a", "a", "cycle: 'a' -> 'a'");
}

TEST(GraphErrors, MissingUnknownOrNonClosureOutput) {
  expect_error_at(error_of(R"({"nodes": {"d": {"type": "lambert"}}})"), "", "output", "missing");
  expect_error_at(error_of(R"({"nodes": {"d": {"type": "lambert"}}, "output": "e"})"), "", "output",
                  "unknown node 'e'");
  expect_error_at(error_of(R"({"nodes": {"c": {"type": "constant", "value": [1, 0, 0]}}, "output": "c"})"),
                  "", "output", "'c.value' is a colour; a material's output must be a closure");
  expect_error_at(error_of(R"({"type": "vertex_colour"})"), "", "type", "must be a closure node");
}

TEST(GraphErrors, NanAndInfiniteConstants) {
  StubResolver resolver;
  json m = {{"type", "lambert"}, {"color", std::nan("")}};
  expect_error_at(error_of(m, resolver), "", "color", "NaN or infinite");
  m["color"] = {0.5, std::numeric_limits<double>::infinity(), 0.5};
  expect_error_at(error_of(m, resolver), "", "color", "NaN or infinite");
  // Folding a product that overflows is caught on the consuming input.
  expect_error_at(error_of(R"({"nodes": {"x": {"type": "multiply", "a": 1e30, "b": 1e30},
                                         "e": {"type": "emission", "strength": {"link": "x"}}}, "output": "e"})"),
                  "e", "strength", "NaN or infinite value inf (from 'x.result')");
}

TEST(GraphErrors, NegativeWhereNotAllowed) {
  expect_error_at(error_of(R"({"type": "lambert", "color": [0.5, -0.1, 0.5]})"), "", "color",
                  "negative value [0.5, -0.1, 0.5] is not allowed");
  expect_error_at(error_of(R"({"type": "lambert", "color": -0.2})"), "", "color", "negative value -0.2");
  expect_error_at(error_of(R"({"type": "emission", "strength": -1})"), "", "strength", "negative value -1");
  expect_error_at(error_of(R"({"nodes": {"s": {"type": "spectrum", "name": "D65", "scale": -2},
                                         "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})"),
                  "s", "scale", "below the minimum 0");
  // A negative albedo computed by constant folding is caught too.
  expect_error_at(error_of(R"({"nodes": {"x": {"type": "multiply", "a": -1, "b": 0.5},
                                         "d": {"type": "lambert", "color": {"link": "x"}}}, "output": "d"})"),
                  "d", "color", "negative value -0.5 (from 'x.result')");
}

TEST(GraphErrors, InlineSpectrumTables) {
  expect_error_at(error_of(R"({"type": "lambert", "color": {"wavelengths": [400, 500], "values": [0.5]}})"),
                  "", "color", "'values' must have as many entries as 'wavelengths' (1 and 2)");
  expect_error_at(
      error_of(R"({"type": "lambert", "color": {"wavelengths": [500, 400], "values": [0.5, 0.6]}})"), "",
      "color", "not strictly increasing at index 1");
  expect_error_at(error_of(R"({"type": "lambert", "color": {"wavelengths": [400], "values": [0.5]}})"), "",
                  "color", "fewer than 2 points");
  expect_error_at(
      error_of(R"({"type": "lambert", "color": {"values": [0.5, 0.6]}})"), "", "color",
      R"({"wavelengths": [...], "values": [...]} or {"blackbody": ...}, or {"link": "node[.output]"}; got)");
  expect_error_at(error_of(R"({"type": "lambert", "color": {"wavelengths": [400, 500]}})"), "", "color",
                  "'wavelengths' needs 'values'");
  expect_error_at(
      error_of(
          R"({"type": "lambert", "color": {"wavelengths": [400, 500], "values": [0.5, 0.6], "column": "x"}})"),
      "", "color", "'column' needs 'file'");
  expect_error_at(
      error_of(R"({"type": "lambert", "color": {"wavelengths": [400, 500], "values": [0.5, -0.6]}})"), "",
      "color", "negative value");
}

TEST(GraphErrors, MixFactorOutOfRange) {
  expect_error_at(error_of(R"({"nodes": {"a": {"type": "lambert"}, "b": {"type": "lambert", "color": 0.2},
                                         "x": {"type": "mix", "a": {"link": "a"}, "b": {"link": "b"}, "factor": 1.5}},
                               "output": "x"})"),
                  "x", "factor", "value 1.5 is outside [0, 1]");
}

TEST(GraphErrors, MissingTextureFileNamesThePath) {
  StubResolver resolver("/data/scenes");
  const json m = json::parse(R"({"nodes": {"t": {"type": "texture", "file": "rock.jpg"},
                                           "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"})");
  expect_error_at(error_of(m, resolver), "t", "file", "/data/scenes/rock.jpg");
}

TEST(GraphErrors, TextureChannelOutOfRange) {
  StubResolver resolver;
  resolver.add_texture("mask.png", 1);
  const json m = json::parse(R"({"nodes": {"t": {"type": "texture", "file": "mask.png", "channel": 2},
                                           "e": {"type": "emission", "strength": {"link": "t.value"}}},
                                 "output": "e"})");
  expect_error_at(error_of(m, resolver), "t", "channel", "has 1 channel(s)");
}

TEST(GraphErrors, BadParameterValues) {
  StubResolver resolver;
  resolver.add_texture("a.png", 3);
  json m = json::parse(R"({"nodes": {"t": {"type": "texture", "file": "a.png", "colorspace": "aces"},
                                     "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"})");
  expect_error_at(error_of(m, resolver), "t", "colorspace", "'aces' is not one of: auto, srgb, linear");
  m["nodes"]["t"].erase("colorspace");
  m["nodes"]["t"]["channel"] = 0.5;
  expect_error_at(error_of(m, resolver), "t", "channel", "expected an integer");
  m["nodes"]["t"].erase("file");
  m["nodes"]["t"]["channel"] = 0;
  expect_error_at(error_of(m, resolver), "t", "file", "missing required parameter");
}

// Integer parameters are range-checked as the JSON number, before any conversion could wrap them; a
// boolean is not an integer.
TEST(GraphErrors, IntegerParametersNeverWrap) {
  StubResolver resolver;
  resolver.add_texture("a.png", 3);
  json m = json::parse(R"({"nodes": {"t": {"type": "texture", "file": "a.png"},
                                     "d": {"type": "lambert", "color": {"link": "t.color"}}}, "output": "d"})");
  for (const char* value : {"4294967297", "18446744073709551615", "1e300"}) {
    m["nodes"]["t"]["channel"] = json::parse(value);
    expect_error_at(error_of(m, resolver), "t", "channel", "32-bit integer");
  }
  m["nodes"]["t"]["channel"] = -1;
  expect_error_at(error_of(m, resolver), "t", "channel", "below the minimum 0");
  m["nodes"]["t"]["channel"] = true;
  expect_error_at(error_of(m, resolver), "t", "channel", "expected an integer, got true");
  expect_error_at(error_of(R"({"type": "dielectric", "opaque": true})"), "", "opaque", "expected an integer");
  expect_error_at(error_of(R"({"type": "dielectric", "opaque": 4294967297})"), "", "opaque",
                  "above the maximum 1");
}

// Numbers that are finite doubles but infinite or zero as floats.
TEST(GraphErrors, NumbersOutsideSinglePrecision) {
  expect_error_at(error_of(R"({"type": "lambert", "color": 1e-50})"), "", "color", "0 in single precision");
  expect_error_at(error_of(R"({"type": "lambert", "color": [0.5, 1e-39, 0.5]})"), "", "color",
                  "smallest normal");
  expect_error_at(error_of(R"({"type": "emission", "strength": 1e39})"), "", "strength",
                  "infinite in single precision");
  expect_error_at(error_of(R"({"nodes": {"s": {"type": "spectrum", "name": "D65", "scale": 1e39},
                                         "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})"),
                  "s", "scale", "infinite in single precision");
  expect_error_at(error_of(R"({"type": "emission", "color": {"name": "D65", "scale": 1e-50}})"), "", "color",
                  "0 in single precision");
  expect_error_at(error_of(R"({"type": "emission", "color": {"blackbody": 1e-50}})"), "", "color",
                  "0 in single precision");
}

// The first negative entry of a CSV named by its wavelength, in an emission colour.
TEST(GraphErrors, NegativeEmissionSpectrumNamesTheWavelength) {
  const auto dir = scratch_dir();
  StubResolver resolver(dir);
  std::ofstream(dir / "cross.csv") << "nm,value\n400,1\n480,0.2\n520,-0.1\n700,1\n";
  expect_error_at(error_of(json::parse(R"({"type": "emission", "color": {"file": "cross.csv"}})"), resolver),
                  "", "color", "-0.1 at 520 nm");
}

TEST(GraphErrors, MissingSpectrumFileNamesThePath) {
  StubResolver resolver("/data/scenes");
  expect_error_at(error_of(json::parse(R"({"type": "lambert", "color": {"file": "red.csv"}})"), resolver), "",
                  "color", "/data/scenes/red.csv");
  const json m = json::parse(R"({"nodes": {"s": {"type": "spectrum", "file": "spd/lamp.csv"},
                                           "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})");
  expect_error_at(error_of(m, resolver), "s", "file", "/data/scenes/spd/lamp.csv");
}

TEST(GraphErrors, BadSpectrumExtrapolation) {
  // Node parameter: one of the two names, and only with a file.
  expect_error_at(error_of(R"({"nodes": {"s": {"type": "spectrum", "file": "x.csv", "extrapolate": "none"},
                                         "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})"),
                  "s", "extrapolate", "'none' is not one of: clamp, zero");
  expect_error_at(error_of(R"({"nodes": {"s": {"type": "spectrum", "name": "D65", "extrapolate": "zero"},
                                         "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})"),
                  "s", "extrapolate", "'extrapolate' applies to 'file' only");
  // Spectrum literal: the same rules, named by the input.
  expect_error_at(error_of(R"({"type": "emission", "color": {"file": "x.csv", "extrapolate": "none"}})"), "",
                  "color", "'extrapolate' must be \"clamp\" or \"zero\", got \"none\"");
  expect_error_at(error_of(R"({"type": "emission", "color": {"file": "x.csv", "extrapolate": 0}})"), "",
                  "color", "'extrapolate' must be \"clamp\" or \"zero\", got 0");
  expect_error_at(error_of(R"({"type": "emission", "color": {"name": "D65", "extrapolate": "zero"}})"), "",
                  "color", "'extrapolate' needs 'file'");
}

TEST(GraphErrors, UnknownSpectrumName) {
  expect_error_at(error_of(R"({"type": "emission", "color": {"name": "D66"}})"), "", "color", "D66");
  expect_error_at(error_of(R"({"nodes": {"s": {"type": "spectrum", "name": "D66"},
                                         "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})"),
                  "s", "name", "D66");
  expect_error_at(error_of(R"({"nodes": {"s": {"type": "spectrum", "name": "D65", "file": "x.csv"},
                                         "e": {"type": "emission", "color": {"link": "s"}}}, "output": "e"})"),
                  "s", "name", "exactly one of 'file' and 'name'");
}

TEST(GraphErrors, MalformedInputValues) {
  expect_error_at(error_of(R"({"type": "lambert", "color": [0.5, 0.5]})"), "", "color", "exactly 3 numbers");
  expect_error_at(error_of(R"({"type": "lambert", "color": "red"})"), "", "color", "expected a number");
  expect_error_at(error_of(R"({"type": "lambert", "color": {"link": 3}})"), "", "color", "a link is written");
}

TEST(GraphErrors, ConflictingSpectralRolesNeedAnExplicitConversion) {
  StubResolver resolver;
  resolver.add_texture("a.png", 3);
  // One sum, used both as an albedo and as an emission colour: its colour operand has no single
  // meaning as a spectrum.
  const json m = json::parse(R"({"nodes": {
      "t": {"type": "texture", "file": "a.png"},
      "s": {"type": "add", "a": {"link": "t.color"}, "b": {"name": "D65"}},
      "d": {"type": "lambert", "color": {"link": "s"}},
      "e": {"type": "emission", "color": {"link": "s"}},
      "out": {"type": "add", "a": {"link": "d"}, "b": {"link": "e"}}}, "output": "out"})");
  expect_error_at(error_of(m, resolver), "s", "a", "rgb_to_spectrum");
}

}  // namespace
}  // namespace ochre::test::graph_error_test

namespace ochre::test::graph_error_test {
namespace {

std::string numbered(const char* prefix, int i) {
  std::string name = prefix;
  name += std::to_string(i);
  return name;
}

TEST(GraphErrors, TooManyLobes) {
  // Nine distinct lambert closures summed: a Closure holds at most 8 lobes.
  nlohmann::json nodes = nlohmann::json::object();
  for (int i = 0; i < 9; ++i) nodes[numbered("l", i)] = {{"type", "lambert"}, {"color", 0.1 * (i + 1)}};
  std::string previous = "l0";
  for (int i = 1; i < 9; ++i) {
    const std::string sum = numbered("s", i);
    nodes[sum] = {{"type", "add"}, {"a", {{"link", previous}}}, {"b", {{"link", numbered("l", i)}}}};
    previous = sum;
  }
  StubResolver resolver;
  try {
    compile_material({{"nodes", nodes}, {"output", previous}}, "m", kSceneFile, resolver);
    ADD_FAILURE() << "nine lobes accepted";
  } catch (const GraphError& e) {
    EXPECT_NE(e.reason().find("9 BSDF lobes; at most 8"), std::string::npos) << e.what();
  }
  // Eight are fine.
  nodes.erase("l8");
  nodes.erase("s8");
  EXPECT_NO_THROW(compile_material({{"nodes", nodes}, {"output", "s7"}}, "m", kSceneFile, resolver));
}

}  // namespace
}  // namespace ochre::test::graph_error_test
