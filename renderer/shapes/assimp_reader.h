#pragma once
// Checks that keep Assimp 5.2 from hanging or aborting on malformed mesh files (found by fuzzing,
// docs/validation.md "Fuzzing"); renderer/shapes/mesh_file_reader.h runs them around its import.

#include <assimp/scene.h>

#include <filesystem>
#include <string>

namespace ochre {

// A file that is a PLY by its extension or its first bytes ("ply") must have a well-formed header up to its
// end_header line (P. Bourke, "PLY - Polygon File Format"): Assimp's PLY reader loops forever on some
// malformed ones (no end_header, a misspelt keyword, an unknown type). Throws InputError naming the line.
void check_ply_header(const std::filesystem::path& file);

// Every face of a scene read without post-processing has vertices, all of them in range (a PLY whose vertex
// count is smaller than its vertex lines): Assimp's post-processing asserts (abort) or reads out of bounds.
void check_mesh_faces(const aiScene& scene, const std::string& where);

}  // namespace ochre
