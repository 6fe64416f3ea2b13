#pragma once
// ControlMesh: the polygonal control cage of a subdivision surface (faces of any size, not
// triangulated), with face-varying UVs, per-vertex colours and edge/vertex sharpness tags, and its
// importer.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "materials/core/vec3.h"
#include "renderer/geometry/transform.h"

namespace ochre {

struct ControlMesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<int> face_sizes;                    // vertices per face (>= 3)
  std::vector<int> face_vertices;                 // sum(face_sizes) indices into positions, counter-clockwise
  std::vector<Vec2> uvs;                          // face-varying uv values (may be empty)
  std::vector<int> face_uv_indices;               // one per face corner into uvs (empty when uvs is empty)
  std::vector<Vec3> colours;                      // per vertex, linear Rec.709 RGB (may be empty)
  std::vector<std::pair<int, int>> crease_edges;  // vertex pairs of creased edges
  std::vector<float> crease_sharpness;            // one per crease edge; >= 10 is infinitely sharp
  std::vector<int> corner_vertices;               // sharp ("corner") vertices
  std::vector<float> corner_sharpness;            // one per corner vertex

  size_t face_count() const { return face_sizes.size(); }
  bool all_triangles() const;

  // Throws InputError starting with `where` when there are no faces, a face has fewer than 3
  // vertices or passes through a vertex twice, face_vertices/face_uv_indices do not have one entry per
  // face corner, an index (vertex, uv, crease, corner) is out of range, colours are sized differently
  // from positions, a sharpness is negative or NaN, or a position/uv/colour is not finite.
  void validate(const std::string& where) const;
};

// An nx x ny grid of quads covering [-1, 1] x [0, 1] (z = 0, normal +z) with face-varying uv =
// ((x + 1) / 2, y): the flat cage of the subdivision tests and of ochre-bench --micro subdivision.
ControlMesh quad_grid_control_mesh(int nx, int ny);

// Imports the polygons of a mesh file through Assimp WITHOUT triangulation (OBJ, PLY, glTF, ...).
// - All meshes of the file are instanced through the node hierarchy and merged; vertices at exactly
//   the same position are welded, so a UV seam (which the file stores as separate vertices) does
//   not tear the surface apart: uvs become face-varying values instead. A face corner welded onto
//   the corner before it (an edge of zero length) is dropped, and so is a face left with fewer than 3
//   corners; a face that still passes through a vertex twice is an error.
// - UV set 0 and colour set 0 are kept (colours decoded to linear as import_mesh does); file
//   normals are ignored (the subdivision limit surface defines the normals).
// - .obj files are also read for OpenSubdiv's tag extension: "t crease 2/1/0 v0 v1 s" (vertices
//   0-based in the order of the "v" lines; more vertices give a chain of creased edges) and
//   "t corner 1/1/0 v s". The slash counts may omit the trailing "/0".
// - `to_world` is applied to the positions; a mirroring transform reverses the face winding.
// Errors (missing file, parse failure, no polygons, bad tags) throw InputError naming the file.
// `warnings`, when given, receives float_detail_warning's warning (renderer/shapes/float_detail.h).
ControlMesh import_control_mesh(const std::filesystem::path& file, const Transform& to_world,
                                std::vector<std::string>* warnings = nullptr);

}  // namespace ochre
