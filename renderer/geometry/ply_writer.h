#pragma once
// A triangle mesh as a binary little-endian PLY file (the format the mesh readers and the Blender add-on
// read): per vertex x y z, then nx ny nz, s t and red green blue where the mesh has them, then one
// `vertex_indices` list of three per triangle. `ochre export-mesh` writes the meshes a scene renders
// (subdivided and displaced) with it (docs/cli.md, "ochre export-mesh").

#include <filesystem>

#include "materials/core/vec3d.h"
#include "renderer/geometry/mesh.h"

namespace ochre {

// Writes `mesh` with every position moved by `offset` (added in double precision, then rounded to float
// once: the scene's rendering origin, so that the file holds world coordinates) to `path` through a
// temporary file renamed over it when complete; throws ImageError naming the path when it cannot.
// Colours are written as 8-bit sRGB-encoded values (linear Rec.709 clamped to [0, 1]), as PLY readers expect.
void write_ply(const Mesh& mesh, const Vec3d& offset, const std::filesystem::path& path);

}  // namespace ochre
