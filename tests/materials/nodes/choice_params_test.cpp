// Choice parameters (materials/nodes/node_choices.h): for every node of the registry and every parameter
// that takes one of a list of words, a word that is not declared is an error naming the node and the
// parameter and listing the words, both from the compiler (a GraphError) and from the node's own
// prepare() called without the parser (a NodeError: no silent fallback to a default), and every declared
// word is read.

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "materials/graph/graph_error.h"
#include "materials/material_test_support.h"
#include "materials/nodes/node_choices.h"
#include "materials/nodes/node_registry.h"

namespace ochre::test::choice_params_test {
namespace {

using nlohmann::json;

struct ChoiceParam {
  const NodeDefinition* node;
  const ParamDef* param;
};

std::vector<ChoiceParam> every_choice_param() {
  std::vector<ChoiceParam> out;
  for (const auto& def : NodeRegistry::builtin().definitions())
    for (const ParamDef& p : def->params)
      if (!p.choices.empty()) out.push_back({def.get(), &p});
  return out;
}

std::string test_name(const testing::TestParamInfo<ChoiceParam>& info) {
  return info.param.node->name + "_" + info.param.param->name;
}

void expect_lists_choices(const std::string& message, const ParamDef& p) {
  EXPECT_NE(message.find("'no_such_word' is not one of: "), std::string::npos) << message;
  for (const std::string& word : p.choices) EXPECT_NE(message.find(word), std::string::npos) << message;
}

// The parameters a prepare() sees after the parser: every default, a texture for a required file, and
// `name` set to `value`.
json prepared_params(const NodeDefinition& node, const std::string& name, const std::string& value) {
  json params = json::object();
  for (const ParamDef& p : node.params) {
    if (!p.default_value.is_null()) params[p.name] = p.default_value;
    if (p.required && p.kind == ParamKind::kString) params[p.name] = "t.png";
  }
  params[name] = value;
  return params;
}

class ChoiceParams : public testing::TestWithParam<ChoiceParam> {};

TEST_P(ChoiceParams, UnknownWordIsAGraphErrorNamingNodeAndParameter) {
  const NodeDefinition& node = *GetParam().node;
  const ParamDef& p = *GetParam().param;
  const json material = {
      {"nodes", {{"n", {{"type", node.name}, {p.name, "no_such_word"}}}, {"out", {{"type", "lambert"}}}}},
      {"output", "out"}};
  StubResolver resolver;
  try {
    compile_material(material, "m", kSceneFile, resolver);
    FAIL() << "no error for " << material.dump();
  } catch (const GraphError& e) {
    EXPECT_EQ(e.node(), "n");
    EXPECT_EQ(e.parameter(), p.name);
    const std::string message = e.what();
    EXPECT_NE(message.find("node 'n', parameter '" + p.name + "'"), std::string::npos) << message;
    expect_lists_choices(message, p);
  }
}

TEST_P(ChoiceParams, PrepareRejectsAnUnknownWordWithoutTheParser) {
  const NodeDefinition& node = *GetParam().node;
  const ParamDef& p = *GetParam().param;
  ASSERT_NE(node.prepare, nullptr) << "a choice nothing reads";
  StubResolver resolver;
  resolver.add_texture("t.png", 3);
  const json params = prepared_params(node, p.name, "no_such_word");
  try {
    node.prepare(PrepareArgs{params, resolver, node});
    FAIL() << "no error for " << params.dump();
  } catch (const NodeError& e) {
    EXPECT_EQ(e.parameter(), p.name);
    expect_lists_choices(e.what(), p);
  }
}

TEST_P(ChoiceParams, PrepareReadsEveryDeclaredWord) {
  const NodeDefinition& node = *GetParam().node;
  const ParamDef& p = *GetParam().param;
  StubResolver resolver;
  resolver.add_texture("t.png", 3);
  for (const std::string& word : p.choices) {
    const json params = prepared_params(node, p.name, word);
    // Other faults may remain (a spectrum node needs a file or a name), but none of this parameter, and no
    // table that disagrees with the declared words (std::logic_error).
    try {
      node.prepare(PrepareArgs{params, resolver, node});
    } catch (const NodeError& e) {
      EXPECT_NE(e.parameter(), p.name) << word << ": " << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, ChoiceParams, testing::ValuesIn(every_choice_param()), test_name);

// A node of its own: one choice with a default, one without.
enum class Flavour { kSweet, kSour };
constexpr std::array kFlavours{Choice{"sweet", Flavour::kSweet}, Choice{"sour", Flavour::kSour}};

NodeDefinition test_node() {
  NodeDefinition d;
  d.name = "test";
  ParamDef flavour;
  flavour.name = "flavour";
  flavour.default_value = "sweet";
  flavour.choices = choice_names(kFlavours);
  ParamDef colour;
  colour.name = "colour";
  colour.choices = {"red", "green"};
  d.params = {flavour, colour};
  return d;
}

TEST(ChoiceReading, WordsIndicesAndTableValues) {
  const NodeDefinition node = test_node();
  StubResolver resolver;
  const json params = {{"flavour", "sour"}, {"colour", "green"}};
  const PrepareArgs args{params, resolver, node};
  EXPECT_EQ(choice_index(args, "flavour"), 1);
  EXPECT_EQ(choice_value(args, "flavour", kFlavours), Flavour::kSour);
  EXPECT_EQ(choice_name(args, "colour"), "green");
  EXPECT_EQ(choice_index(args, "colour"), 1);
}

TEST(ChoiceReading, AnAbsentChoiceWithoutDefaultIsMinusOne) {
  const NodeDefinition node = test_node();
  StubResolver resolver;
  const json params = json::object();
  const PrepareArgs args{params, resolver, node};
  EXPECT_EQ(choice_index(args, "colour"), -1);
  EXPECT_FALSE(choice_name(args, "colour").has_value());
  // A value read through a table must be there (the parser gives every default).
  EXPECT_THROW(choice_value(args, "flavour", kFlavours), std::logic_error);
}

TEST(ChoiceReading, ANonStringValueIsANodeError) {
  const NodeDefinition node = test_node();
  StubResolver resolver;
  const json params = {{"colour", 3}};
  try {
    choice_index(PrepareArgs{params, resolver, node}, "colour");
    FAIL();
  } catch (const NodeError& e) {
    EXPECT_EQ(e.parameter(), "colour");
    EXPECT_NE(std::string(e.what()).find("expected a string"), std::string::npos) << e.what();
  }
}

TEST(ChoiceReading, ATableThatIsNotTheDeclaredWordsIsAProgrammingError) {
  const NodeDefinition node = test_node();
  StubResolver resolver;
  const json params = {{"colour", "red"}};
  const PrepareArgs args{params, resolver, node};
  constexpr std::array kColours{Choice{"red", 0}, Choice{"blue", 1}};
  EXPECT_THROW(choice_value(args, "colour", kColours), std::logic_error);
  EXPECT_THROW(choice_index(args, "size"), std::logic_error);  // not a declared choice parameter
}

}  // namespace
}  // namespace ochre::test::choice_params_test
