// docs/scene-format.md documents every registered shape and light type with all its keys and their
// defaults, and documents nothing that is not registered (the tables are checked against the declarations
// of renderer/shapes/shape_registry.cpp and renderer/lights/light_registry.cpp).
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "renderer/lights/light_type.h"
#include "renderer/shapes/shape_type.h"
#include "support/test_paths.h"
#include "support/text_files.h"

namespace ochre::test::type_registry_docs_test {
namespace {

// The text of the section "## `heading`" up to the next "## " heading.
std::string section(const std::string& doc, const std::string& heading) {
  const size_t start = doc.find("\n## " + heading + "\n");
  if (start == std::string::npos) return "";
  const size_t end = doc.find("\n## ", start + 1);
  return doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The table row of `type` ("| `type` | keys | ... |"), or "" when there is none.
std::string row(const std::string& text, const std::string& type) {
  const size_t start = text.find("\n| `" + type + "` |");
  if (start == std::string::npos) return "";
  return text.substr(start + 1, text.find('\n', start + 1) - start - 1);
}

// The second column of a row: the keys.
std::string keys_column(const std::string& row_text) {
  const size_t first = row_text.find('|', 1);
  const size_t second = row_text.find('|', first + 1);
  return row_text.substr(first + 1, second - first - 1);
}

// Every type named in the first column of the section's first table.
std::set<std::string> documented_types(const std::string& text) {
  std::set<std::string> types;
  std::istringstream lines(text);
  bool in_table = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    if (line.rfind("| `", 0) == 0) types.insert(line.substr(3, line.find('`', 3) - 3));
  }
  return types;
}

// Each declared field appears in the keys column as `name`, followed by " (default)" when it has one.
void expect_fields_documented(const std::string& keys, const std::string& type,
                              const std::vector<FieldSpec>& fields) {
  for (const FieldSpec& f : fields) {
    const std::string name = "`" + f.name + "`";
    EXPECT_NE(keys.find(name), std::string::npos) << type << ": key " << f.name << " is not documented";
    if (!f.default_text.empty()) {
      EXPECT_NE(keys.find(name + " (" + f.default_text + ")"), std::string::npos)
          << type << ": key " << f.name << " should read " << name << " (" << f.default_text << ")";
    }
  }
}

TEST(TypeRegistryDocs, EveryShapeTypeAndKeyIsDocumented) {
  const std::string text = section(read_file_contents(source_dir() / "docs" / "scene-format.md"), "shapes");
  ASSERT_FALSE(text.empty());
  std::set<std::string> registered;
  for (const ShapeType& type : ShapeRegistry::builtin().types()) {
    registered.insert(type.name);
    const std::string r = row(text, type.name);
    ASSERT_FALSE(r.empty()) << "no row for shape type " << type.name;
    expect_fields_documented(keys_column(r), type.name, type.fields);
  }
  EXPECT_EQ(documented_types(text), registered);
  // The common keys are described above the table.
  const std::string intro = text.substr(0, text.find("\n|"));
  for (const FieldSpec& f : common_shape_fields())
    if (f.name != "type") {
      EXPECT_NE(intro.find("`" + f.name + "`"), std::string::npos) << f.name;
    }
}

TEST(TypeRegistryDocs, EveryLightTypeAndKeyIsDocumented) {
  const std::string text = section(read_file_contents(source_dir() / "docs" / "scene-format.md"), "lights");
  ASSERT_FALSE(text.empty());
  std::set<std::string> registered;
  for (const LightType& type : LightRegistry::builtin().types()) {
    registered.insert(type.name);
    const std::string r = row(text, type.name);
    ASSERT_FALSE(r.empty()) << "no row for light type " << type.name;
    expect_fields_documented(keys_column(r), type.name, type.fields);
  }
  EXPECT_EQ(documented_types(text), registered);
}

// The registries refuse a second type of the same name and a shape field that repeats a common one.
TEST(TypeRegistryDocs, RegistriesRefuseDuplicates) {
  ShapeRegistry shapes;
  shapes.add(*ShapeRegistry::builtin().find("sphere"));
  EXPECT_THROW(shapes.add(*ShapeRegistry::builtin().find("sphere")), std::logic_error);
  ShapeType clash = *ShapeRegistry::builtin().find("disk");
  clash.name = "clash";
  clash.fields.push_back(boolean_field("flip_normals", false, "repeats a common field"));
  EXPECT_THROW(shapes.add(clash), std::logic_error);
  LightRegistry lights;
  lights.add(*LightRegistry::builtin().find("point"));
  EXPECT_THROW(lights.add(*LightRegistry::builtin().find("point")), std::logic_error);
}

}  // namespace
}  // namespace ochre::test::type_registry_docs_test
