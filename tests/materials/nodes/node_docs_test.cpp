// docs/nodes.md documents every built-in node with all its inputs, parameters and outputs.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

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

// The text from the node's "### `name`" heading to the next heading.
std::string section(const std::string& doc, const std::string& node) {
  const size_t start = doc.find("### `" + node + "`");
  if (start == std::string::npos) return "";
  const size_t end = doc.find("\n#", start + 1);
  return doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(NodeDocs, EveryNodeAndSocketIsDocumented) {
  const std::string doc = read_text(source_dir() / "docs" / "nodes.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& def : NodeRegistry::builtin().definitions()) {
    const std::string text = section(doc, def->name);
    ASSERT_FALSE(text.empty()) << "no section for node " << def->name;
    auto expect_row = [&](const std::string& kind, const std::string& name) {
      EXPECT_NE(text.find("| " + kind + " | `" + name + "` |"), std::string::npos)
          << def->name << ": " << kind << " " << name;
    };
    for (const SocketDef& s : def->inputs) expect_row("input", s.name);
    for (const ParamDef& p : def->params) expect_row("parameter", p.name);
    for (const OutputDef& o : def->outputs) expect_row("output", o.name);
  }
}

}  // namespace
}  // namespace ochre::test::node_docs_test
