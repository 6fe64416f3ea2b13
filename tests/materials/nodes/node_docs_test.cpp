// docs/nodes.md documents every built-in node with all its inputs, parameters and outputs, the research
// parameters (ParamDef::research) in the node's "Research parameters" table and only there.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "materials/nodes/node_registry.h"
#include "support/test_paths.h"

namespace ochre::test::node_docs_test {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

constexpr const char* kResearchHeading = "\n#### Research parameters\n";

// The text from the node's "### `name`" heading to the next heading of the same or a higher level.
std::string section(const std::string& doc, const std::string& node) {
  const size_t start = doc.find("### `" + node + "`");
  if (start == std::string::npos) return "";
  const size_t end = std::min(doc.find("\n### ", start + 1), doc.find("\n## ", start + 1));
  return doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(NodeDocs, EveryNodeAndSocketIsDocumented) {
  const std::string doc = read_text(source_dir() / "docs" / "nodes.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& def : NodeRegistry::builtin().definitions()) {
    const std::string text = section(doc, def->name);
    ASSERT_FALSE(text.empty()) << "no section for node " << def->name;
    // The node's own table and prose, then its research table (empty when it has none).
    const size_t split = text.find(kResearchHeading);
    const std::string own = text.substr(0, split);
    const std::string research = split == std::string::npos ? "" : text.substr(split);
    auto has_row = [](const std::string& part, const std::string& kind, const std::string& name) {
      return part.find("| " + kind + " | `" + name + "` |") != std::string::npos;
    };
    for (const SocketDef& s : def->inputs)
      EXPECT_TRUE(has_row(own, "input", s.name)) << def->name << ": " << s.name;
    for (const OutputDef& o : def->outputs)
      EXPECT_TRUE(has_row(own, "output", o.name)) << def->name << ": " << o.name;
    for (const ParamDef& p : def->params) {
      const std::string& table = p.research ? research : own;
      const std::string& other = p.research ? own : research;
      EXPECT_TRUE(has_row(table, "parameter", p.name))
          << def->name << ": parameter " << p.name << (p.research ? " not in the research table" : "");
      EXPECT_FALSE(has_row(other, "parameter", p.name))
          << def->name << ": parameter " << p.name << (p.research ? " is research" : " is not research");
    }
    if (!research.empty()) {
      bool any_research = false;
      for (const ParamDef& p : def->params) any_research = any_research || p.research;
      EXPECT_TRUE(any_research) << def->name << ": a research table but no research parameter";
    }
  }
}

// The registry's side of the same rule: the research switches of the powder (docs/materials/powder.md,
// 'Product and research settings'), Lambert-sphere (docs/materials/lambert_sphere.md, 'kd -> c mapping')
// and groove (docs/materials/vgroove.md) closures are marked, no other parameter is, and each says so at
// the start of its description.
TEST(NodeDocs, ResearchParametersAreMarkedAndSaySo) {
  const std::set<std::string> expected = {
      "powder.ladder",           "powder.ladder_decay",    "powder.normalisation",
      "powder.surface",          "powder.surface_sigma",   "powder.tau",
      "powder.sampling",         "lambert_sphere.mapping", "vgroove.model",
      "vgroove.max_reflections", "microgroove.model",      "microgroove.max_reflections"};
  std::set<std::string> marked;
  for (const auto& def : NodeRegistry::builtin().definitions()) {
    for (const ParamDef& p : def->params) {
      EXPECT_EQ(p.doc.rfind("research: ", 0) == 0, p.research) << def->name << ": " << p.name;
      if (p.research) marked.insert(def->name + "." + p.name);
    }
  }
  EXPECT_EQ(marked, expected);
}

}  // namespace
}  // namespace ochre::test::node_docs_test
