#pragma once
// Mesh import through Assimp: OBJ, PLY (with vertex colours), glTF/GLB and every other format
// Assimp reads.
//
// What the importer does:
// - Triangulates polygons and skips point and line primitives; joins identical vertices.
// - Keeps the file's normals when present; generates smooth normals only for meshes without
//   them and only when options.smooth_normals is set (otherwise such meshes shade flat).
// - Keeps UV set 0 (v = 0 is the bottom row of an image, OBJ/OpenGL convention; Assimp converts
//   glTF's top-left origin to it) and vertex colour set 0 (alpha is dropped).
// - Merges all meshes of the file, instanced through the node hierarchy with their node
//   transforms, into one Mesh named after the file stem, then applies `to_world` (normals by the
//   inverse transpose, winding reversed for mirroring transforms). Materials in the file are
//   ignored: the scene assigns one material to the whole mesh (import_mesh_by_material keeps one mesh
//   per file material instead). When only some of the merged
//   meshes have normals, the others get flat face normals on unshared vertices; when only some
//   have UVs or colours, the others get uv (0, 0) and colour (1, 1, 1).
// - Vertex colours become linear Rec.709:
//     * PLY colours stored as integers (uchar red/green/blue, also ushort etc.) are 8/16-bit
//       display colours: sRGB-encoded, decoded with the IEC 61966-2-1 transfer function.
//     * PLY colours stored as float/double are taken as linear (they are not display codes).
//     * OBJ "v x y z r g b" colours are sRGB-encoded: the format has no colour-space rule and
//       the writers that emit them (MeshLab, scanners) write 8-bit display colours / 255.
//     * glTF COLOR_0 is linear by the glTF 2.0 specification, and other formats are taken as
//       linear.
// - Errors (missing or unreadable file, parse failure, no triangles, non-finite data) throw
//   InputError whose message starts with the file path.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "renderer/geometry/mesh.h"
#include "renderer/geometry/transform.h"

namespace ochre {

struct MeshImportOptions {
  bool smooth_normals = false;  // generate smooth normals for meshes that have none
  bool flip_uv_v = false;       // v -> 1 - v after import
  bool face_normals = false;    // drop the file's normals: flat shading (Mitsuba's face_normals)
};

// `warnings`, when given, receives the warning of float_detail_warning (renderer/shapes/float_detail.h) when
// the file's coordinates are too large for its detail in single precision.
Mesh import_mesh(const std::filesystem::path& file, const Transform& to_world,
                 const MeshImportOptions& options = {}, std::vector<std::string>* warnings = nullptr);

// The triangles of one material of a file (an OBJ's MTL material, a glTF material) and the texture files
// that material names, by MTL keyword (map_Kd, map_Ks, map_Ka, map_Ns, map_d, map_bump, norm; a glTF base
// colour map is map_Kd), as written in the file (relative to the mesh file's folder).
struct MeshMaterialPart {
  std::string material;
  std::map<std::string, std::string> textures;
  Mesh mesh;  // named "<file stem>/<material>"
};

// As import_mesh, but one mesh per material of the file (in the file's material order; materials without
// triangles are left out) instead of one merged mesh: photogrammetry exports with several texture atlases.
std::vector<MeshMaterialPart> import_mesh_by_material(const std::filesystem::path& file,
                                                      const Transform& to_world,
                                                      const MeshImportOptions& options = {},
                                                      std::vector<std::string>* warnings = nullptr);

// How vertex colours of a file are encoded (exposed for tests and documentation tools).
enum class VertexColourEncoding { Linear, Srgb };
VertexColourEncoding vertex_colour_encoding(const std::filesystem::path& file);

// IEC 61966-2-1 sRGB decoding of one channel in [0, 1].
float srgb_to_linear(float encoded);

}  // namespace ochre
