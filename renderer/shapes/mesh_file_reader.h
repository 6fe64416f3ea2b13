#pragma once
// Assimp's file reading, the way every reader of user files in ochre works (spectra/input_file.h): the
// mesh file and every file it names (an OBJ's material library, a glTF's buffers) must be a regular file
// of at most the mesh limit, opened so that a FIFO cannot hang the import. Also:
// - Triangulation is bounded: Assimp's ear clipping costs about the cube of a polygon's vertex count
//   (one polygon of 100 000 vertices takes minutes), so polygons whose total cost exceeds that of one
//   polygon of kMaxTriangulatedPolygon vertices are refused before Assimp starts on them.
// - A long import reports its progress (renderer/util/load_progress.h).

#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>

#include "renderer/geometry/transform.h"

namespace ochre {

inline constexpr double kMaxTriangulatedPolygon = 30000;

// Reads `file` with the post-processing steps `flags` (aiProcess_*). Returns the scene, owned by
// `importer`. Throws InputError starting with the file path when the file (or one it names) is not an
// acceptable input, its polygons are too large to triangulate, or Assimp cannot import it.
const aiScene* read_mesh_file(Assimp::Importer& importer, const std::filesystem::path& file, unsigned flags);

// A node's transformation in the scene Assimp read, as ours.
Transform to_transform(const aiMatrix4x4& a);

}  // namespace ochre
