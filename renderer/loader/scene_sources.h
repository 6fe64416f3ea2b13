#pragma once
// The JSON a scene is made of before anything is built from it (docs/scene-format.md, "Including files"
// and "Presets"):
// - "include": ["a.json", ...] reads other files (materials, shapes and lights, e.g. a pigment library or
//   a cave), recursively, each file once; paths inside an included file stay relative to that file, and
//   errors in it name it.
// - a material node {"type": "material", "material": "name"} is replaced by the graph of the material of
//   that name (inlined under the node's name), so library pigments can be layered with mix nodes.
// - "presets": {"name": {...}} holds named variants (film, integrator, output, camera settings and
//   shapes patched by name); load_scene_sources applies the one asked for.
// Every problem throws InputError naming the file and the field.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ochre {

// One material, shape or light and the file it was written in.
struct SceneItem {
  std::filesystem::path file;  // the file that holds it (paths in it are relative to its folder)
  std::string where;           // its location for messages: "file: shapes[2]"
  std::string name;            // materials: the material name
  nlohmann::json json;
};

struct SceneSources {
  std::filesystem::path file;                        // the main scene file
  std::string name;                                  // what messages call it (its path, or e.g. "<dict>")
  nlohmann::json root;                               // the main file, with the chosen preset applied
  std::vector<SceneItem> materials, shapes, lights;  // included files' first, in include order
};

// Reads `file` and everything it includes, and applies `preset` (nullopt: none). Throws InputError.
SceneSources load_scene_sources(const std::filesystem::path& file, const std::optional<std::string>& preset);
// The same for a scene already read: `root` stands for `file` (relative paths and includes are resolved
// from its folder) and messages call it `name`.
SceneSources load_scene_sources(const nlohmann::json& root, const std::filesystem::path& file,
                                const std::string& name, const std::optional<std::string>& preset);

}  // namespace ochre
