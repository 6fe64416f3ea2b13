#include "renderer/loader/material_templates.h"

#include <fmt/format.h>

#include "spectra/input_error.h"

namespace ochre {

namespace {

bool is_placeholder(const nlohmann::json& value) {
  return value.is_string() && value.get<std::string>().rfind(kMtlPrefix, 0) == 0;
}

template <class Visit>
void for_each_string(nlohmann::json& value, const Visit& visit) {
  if (value.is_string()) {
    visit(value);
  } else if (value.is_structured()) {
    for (auto& child : value) for_each_string(child, visit);
  }
}

}  // namespace

bool is_material_template(const nlohmann::json& material) {
  bool found = false;
  nlohmann::json copy = material;
  for_each_string(copy, [&](const nlohmann::json& s) { found = found || is_placeholder(s); });
  return found;
}

nlohmann::json instantiate_material_template(const nlohmann::json& material,
                                             const std::map<std::string, std::string>& textures,
                                             const std::filesystem::path& mesh_dir,
                                             const std::string& file_material, const std::string& where) {
  nlohmann::json result = material;
  for_each_string(result, [&](nlohmann::json& s) {
    if (!is_placeholder(s)) return;
    const std::string keyword = s.get<std::string>().substr(std::string(kMtlPrefix).size());
    const auto it = textures.find(keyword);
    if (it == textures.end()) {
      std::string known;
      for (const auto& [key, file] : textures) known += (known.empty() ? "" : ", ") + key;
      throw InputError(fmt::format("{}: the file's material '{}' has no {} texture for '{}' (it has: {})",
                                   where, file_material, keyword, s.get<std::string>(),
                                   known.empty() ? "none" : known));
    }
    const std::filesystem::path file(it->second);
    s = (file.is_absolute() ? file : mesh_dir / file).string();
  });
  return result;
}

}  // namespace ochre
