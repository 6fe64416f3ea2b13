#include "renderer/loader/scene_sources.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "renderer/json/json_fields.h"
#include "renderer/json/json_file.h"
#include "renderer/loader/material_templates.h"
#include "spectra/input_error.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

// What only the main scene file may set; an included file holds materials, shapes and lights.
constexpr const char* kMainOnlyKeys[] = {"camera", "film", "integrator", "output", "presets"};

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

// The string `object[key]`, or "" when the member is absent or not a string (the loader reports it later
// with the field's path; reading it here must not throw).
std::string string_member(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

class SourceReader {
 public:
  explicit SourceReader(SceneSources& out) : out_(out) {}

  // Reads `file` (the main scene when `includer` is empty; its JSON is `given` when not null, named `name`
  // in messages) and, depth first, the files it includes.
  void read(const fs::path& file, const std::string& includer, const nlohmann::json* given = nullptr,
            const std::string& name = {}) {
    const fs::path key = fs::weakly_canonical(fs::absolute(file));
    if (std::find(chain_.begin(), chain_.end(), key) != chain_.end()) {
      std::vector<std::string> names;
      for (const fs::path& p : chain_) names.push_back(p.filename().string());
      names.push_back(key.filename().string());
      throw InputError(fmt::format("{}: includes itself: {}", includer, join(names, " -> ")));
    }
    if (!visited_.insert(key).second) return;  // each file once (two fragments may include one library)
    chain_.push_back(key);
    nlohmann::json json;
    try {
      json = given ? *given : read_json_file(file, includer.empty() ? "scene file" : "included scene file");
    } catch (const InputError& e) {
      if (includer.empty()) throw;
      throw InputError(fmt::format("{}: {}", includer, e.what()));
    }
    const bool main = includer.empty();
    if (main) out_.root = json;
    const nlohmann::json& body = main ? out_.root : json;
    const JsonFields top(body, (name.empty() ? file.string() : name) + ":");
    if (!main) check_included_keys(top);
    read_includes(top, file);
    collect(top, file);
    chain_.pop_back();
  }

 private:
  static void check_included_keys(const JsonFields& top) {
    for (const char* key : kMainOnlyKeys)
      if (top.has(key))
        top.fail(key,
                 fmt::format("only the main scene file may set \"{}\" (an included file holds materials, "
                             "shapes and lights)",
                             key));
    top.check_known({"description", "ochre", "include", "materials", "shapes", "lights"});
  }

  void read_includes(const JsonFields& top, const fs::path& file) {
    if (!top.has("include")) return;
    const nlohmann::json& list = top.require("include");
    if (!list.is_array()) top.fail("include", "expected an array of file names");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string where = fmt::format("{}[{}]", top.child("include"), i);
      const std::string name = json_string(list[i], where);
      if (name.empty()) throw InputError(where + ": expected a file name, got an empty string");
      const fs::path path = fs::path(name).is_absolute() ? fs::path(name) : file.parent_path() / name;
      read(path, where);
    }
  }

  void collect(const JsonFields& top, const fs::path& file) {
    if (top.has("materials")) {
      const JsonFields materials(top.require("materials"), top.child("materials"));
      for (const auto& [name, value] : materials.json().items()) {
        if (const auto it = material_files_.find(name); it != material_files_.end())
          materials.fail(name, fmt::format("material '{}' is also defined in {}", name, it->second));
        material_files_[name] = file.string();
        out_.materials.push_back({file, materials.child(name), name, value});
      }
    }
    collect_array(top, file, "shapes", out_.shapes);
    collect_array(top, file, "lights", out_.lights);
  }

  static void collect_array(const JsonFields& top, const fs::path& file, const char* key,
                            std::vector<SceneItem>& items) {
    if (!top.has(key)) return;
    const nlohmann::json& array = top.require(key);
    if (!array.is_array()) top.fail(key, std::string("expected an array of ") + key);
    for (size_t i = 0; i < array.size(); ++i)
      items.push_back({file, fmt::format("{}[{}]", top.child(key), i), "", array[i]});
  }

  SceneSources& out_;
  std::vector<fs::path> chain_;  // the files being read, outermost first (cycle detection)
  std::set<fs::path> visited_;
  std::map<std::string, std::string> material_files_;
};

// --- Material references: {"type": "material", "material": "name"} -------------------------------

// Makes the file names of a node absolute (relative to `dir`): the parameters "file" and "pigment_file"
// and spectrum literals {"file": ...}, so that an inlined node still reads the files beside its own file.
// Template placeholders ("mtl:map_Kd", material_templates.h) stay as they are.
void absolute_file_names(nlohmann::json& node, const fs::path& dir) {
  auto absolute = [&](nlohmann::json& value) {
    if (value.is_string() && value.get<std::string>().rfind(kMtlPrefix, 0) != 0 &&
        fs::path(value.get<std::string>()).is_relative())
      value = fs::absolute(dir / value.get<std::string>()).lexically_normal().string();
  };
  for (auto& [key, value] : node.items()) {
    if (key == "file" || key == "pigment_file") absolute(value);
    if (value.is_object() && value.contains("file")) absolute(value["file"]);
  }
}

class MaterialInliner {
 public:
  explicit MaterialInliner(std::vector<SceneItem>& materials) : materials_(materials) {}

  void run() {
    for (size_t i = 0; i < materials_.size(); ++i) expand(i);
  }

 private:
  // Expands the references of material i (once), after those of the materials it references.
  void expand(size_t i) {
    if (done_.count(i)) return;
    if (std::find(active_.begin(), active_.end(), i) != active_.end()) {
      std::vector<std::string> names;
      for (size_t a : active_) names.push_back("'" + materials_[a].name + "'");
      names.push_back("'" + materials_[i].name + "'");
      throw InputError(
          fmt::format("{}: material references form a cycle: {}", materials_[i].where, join(names, " -> ")));
    }
    active_.push_back(i);
    SceneItem& m = materials_[i];
    if (m.json.is_object() && string_member(m.json, "type") == "material") {
      // A whole material that is a reference: a copy of the one it names.
      const size_t target = find(m.json, m.where);
      expand(target);
      m.json = with_absolute_files(materials_[target]);
    } else if (m.json.is_object() && m.json.contains("nodes") && m.json["nodes"].is_object()) {
      std::vector<std::string> references;
      for (const auto& [name, node] : m.json["nodes"].items())
        if (node.is_object() && string_member(node, "type") == "material") references.push_back(name);
      for (const std::string& name : references) inline_reference(m, name);
    }
    active_.pop_back();
    done_.insert(i);
  }

  size_t find(const nlohmann::json& reference, const std::string& where) {
    const JsonFields f(reference, where);
    f.check_known({"type", "material"});
    const std::string name = f.required_string("material");
    for (size_t j = 0; j < materials_.size(); ++j)
      if (materials_[j].name == name) return j;
    f.fail("material", fmt::format("unknown material '{}'", name));
  }

  // The material's JSON with its nodes' file names made absolute.
  static nlohmann::json with_absolute_files(const SceneItem& material) {
    nlohmann::json json = material.json;
    const fs::path dir = material.file.parent_path();
    if (json.contains("nodes") && json["nodes"].is_object()) {
      for (auto& [name, node] : json["nodes"].items())
        if (node.is_object()) absolute_file_names(node, dir);
    } else if (json.is_object()) {
      absolute_file_names(json, dir);
    }
    return json;
  }

  // Replaces node `name` of material m by the graph of the material it references: the referenced
  // material's output node takes the name `name`, its other nodes become `name/<node>`.
  void inline_reference(SceneItem& m, const std::string& name) {
    nlohmann::json& nodes = m.json["nodes"];
    const std::string where = fmt::format("{}.nodes.{}", m.where, name);
    const size_t target = find(nodes[name], where);
    expand(target);
    const nlohmann::json graph = with_absolute_files(materials_[target]);
    if (!graph.contains("nodes")) {  // a one-node material
      nodes[name] = graph;
      return;
    }
    if (!graph.contains("output") || !graph["output"].is_string() || !graph["nodes"].is_object())
      throw InputError(
          fmt::format("{}: material '{}' has no valid \"output\" to inline", where, materials_[target].name));
    const std::string output = graph["output"].get<std::string>();
    const std::string output_node = output.substr(0, output.find('.'));
    auto renamed = [&](const std::string& node) { return node == output_node ? name : name + "/" + node; };
    nodes.erase(name);
    for (const auto& [node_name, node] : graph["nodes"].items()) {
      const std::string new_name = renamed(node_name);
      if (nodes.contains(new_name))
        throw InputError(fmt::format("{}: inlining material '{}' needs the node name '{}', which is taken",
                                     where, materials_[target].name, new_name));
      nlohmann::json copy = node;
      if (copy.is_object())
        for (auto& [key, value] : copy.items())
          if (value.is_object() && value.contains("link") && value["link"].is_string()) {
            const std::string link = value["link"].get<std::string>();
            const size_t dot = link.find('.');
            const std::string linked = link.substr(0, dot);
            if (graph["nodes"].contains(linked))
              value["link"] = renamed(linked) + (dot == std::string::npos ? "" : link.substr(dot));
          }
      nodes[new_name] = copy;
    }
  }

  std::vector<SceneItem>& materials_;
  std::set<size_t> done_;
  std::vector<size_t> active_;
};

// --- Presets ------------------------------------------------------------------------------------------

constexpr const char* kPresetSettings[] = {"camera", "film", "integrator", "output"};

// Checks the structure of every preset (also those not chosen, so that a typo never passes silently):
// known keys, objects where objects go, and shape names that exist.
void check_presets(const JsonFields& top, const std::vector<SceneItem>& shapes) {
  if (!top.has("presets")) return;
  const JsonFields presets(top.require("presets"), top.child("presets"));
  for (const auto& [name, value] : presets.json().items()) {
    const JsonFields preset(value, presets.child(name));
    preset.check_known({"description", "camera", "film", "integrator", "output", "shapes"});
    preset.string("description", "");
    for (const char* key : kPresetSettings)
      if (preset.has(key)) JsonFields(preset.require(key), preset.child(key));
    if (!preset.has("shapes")) continue;
    const JsonFields patches(preset.require("shapes"), preset.child("shapes"));
    for (const auto& item : patches.json().items()) {
      const std::string& shape = item.key();
      JsonFields(item.value(), patches.child(shape));
      const bool found = std::any_of(shapes.begin(), shapes.end(), [&](const SceneItem& s) {
        return s.json.is_object() && string_member(s.json, "name") == shape;
      });
      if (!found) patches.fail(shape, fmt::format("no shape is named '{}'", shape));
    }
  }
}

void apply_preset(SceneSources& sources, const std::string& name) {
  const JsonFields top(sources.root, sources.name + ":");
  if (!top.has("presets"))
    top.fail("presets", fmt::format("the scene has no presets (asked for '{}')", name));
  const nlohmann::json& presets = top.require("presets");
  if (!presets.contains(name)) {
    std::vector<std::string> known;
    for (const auto& [key, value] : presets.items()) known.push_back(key);
    top.fail("presets", fmt::format("no preset '{}' (known: {})", name, join(known, ", ")));
  }
  const nlohmann::json preset = presets[name];
  for (const char* key : kPresetSettings) {
    if (!preset.contains(key)) continue;
    if (!sources.root.contains(key)) sources.root[key] = nlohmann::json::object();
    sources.root[key].merge_patch(preset[key]);
  }
  if (!preset.contains("shapes")) return;
  for (const auto& [shape, patch] : preset["shapes"].items())
    for (SceneItem& s : sources.shapes)
      if (s.json.is_object() && string_member(s.json, "name") == shape) s.json.merge_patch(patch);
}

}  // namespace

SceneSources load_scene_sources(const fs::path& file, const std::optional<std::string>& preset) {
  return load_scene_sources(read_json_file(file, "scene file"), file, file.string(), preset);
}

SceneSources load_scene_sources(const nlohmann::json& root, const fs::path& file, const std::string& name,
                                const std::optional<std::string>& preset) {
  if (!root.is_object()) throw InputError(fmt::format("{}: a scene must be a JSON object", name));
  SceneSources sources;
  sources.file = file;
  sources.name = name;
  SourceReader(sources).read(file, "", &root, name);
  MaterialInliner(sources.materials).run();
  check_presets(JsonFields(sources.root, name + ":"), sources.shapes);
  if (preset) apply_preset(sources, *preset);
  return sources;
}

}  // namespace ochre
