#pragma once
// The "mesh" shape's file and import options, shared with the loader's meshes with several materials
// (docs/scene-format.md, "Meshes with several materials"), which make one scene mesh per file material.

#include <filesystem>

#include "renderer/json/field_spec.h"
#include "renderer/shapes/mesh_import.h"

namespace ochre {

// The mesh file, relative to `dir` (the folder of the file that holds the shape) unless absolute.
std::filesystem::path mesh_file(const DeclaredFields& f, const std::filesystem::path& dir);
// smooth_normals, face_normals (not both), flip_uv_v.
MeshImportOptions mesh_import_options(const DeclaredFields& f);

}  // namespace ochre
