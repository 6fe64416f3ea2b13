#pragma once
// Reads a mesh file with Assimp for mesh_import and control_mesh, guarded against the inputs that hang or
// abort Assimp 5.2 (found by fuzzing, docs/validation.md "Fuzzing"):
// - a PLY file (by its extension, or its first bytes "ply") whose header is malformed (no end_header
//   line, a misspelt keyword, an unknown type, ...): Assimp's PLY reader loops forever on some;
// - a face without vertices or with a vertex index out of range (a PLY whose vertex count is smaller
//   than its vertex lines): Assimp's post-processing asserts (abort) or reads out of bounds.
// The file is read without post-processing, checked, and only then post-processed.

#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>

namespace ochre {

// The scene of `file` after the post-processing steps `flags` (aiProcess_*). Throws InputError starting
// with the file path when Assimp cannot read it or it fails the checks above.
const aiScene& read_with_assimp(Assimp::Importer& importer, const std::filesystem::path& file,
                                unsigned flags);

}  // namespace ochre
