#pragma once
// Material templates: materials whose texture files are "mtl:<keyword>" (e.g. "mtl:map_Kd") stand for the
// textures that each material of a mesh file names (an OBJ's MTL), so that one scene material serves every
// texture atlas of a photogrammetry export (docs/scene-format.md, "Meshes with several materials").

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace ochre {

inline constexpr const char* kMtlPrefix = "mtl:";

// True when some string in the material is a "mtl:" placeholder.
bool is_material_template(const nlohmann::json& material);

// The material with every "mtl:<keyword>" replaced by the absolute path of the texture `textures` gives
// for that keyword (relative to `mesh_dir`). Throws InputError starting with `where` when the file material
// `file_material` has no texture for a keyword (the message lists those it has).
nlohmann::json instantiate_material_template(const nlohmann::json& material,
                                             const std::map<std::string, std::string>& textures,
                                             const std::filesystem::path& mesh_dir,
                                             const std::string& file_material, const std::string& where);

}  // namespace ochre
