#include "renderer/shapes/mesh_import.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "renderer/shapes/float_detail.h"
#include "renderer/shapes/mesh_file_reader.h"
#include "renderer/util/ascii_case.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

bool is_integer_ply_type(const std::string& type) {
  static const char* const kIntegerTypes[] = {"char", "uchar", "short", "ushort", "int",   "uint",
                                              "int8", "uint8", "int16", "uint16", "int32", "uint32"};
  return std::find(std::begin(kIntegerTypes), std::end(kIntegerTypes), type) != std::end(kIntegerTypes);
}

// Reads the (ASCII) PLY header and reports whether the vertex colour channels are integers.
VertexColourEncoding ply_colour_encoding(const std::filesystem::path& file) {
  InputFile input = InputFile::open(file, kMeshFileInput);
  const std::unique_ptr<std::istream> in = input.stream();
  std::string line;
  for (int lines = 0; lines < 10000 && std::getline(*in, line); ++lines) {
    std::istringstream words(line);
    std::string keyword, type, name;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword != "property") continue;
    words >> type >> name;
    if (name == "red" || name == "r" || name == "diffuse_red") {
      return is_integer_ply_type(type) ? VertexColourEncoding::Srgb : VertexColourEncoding::Linear;
    }
  }
  return VertexColourEncoding::Linear;
}

// One Assimp mesh in its own coordinates, triangles only.
Mesh convert_mesh(const aiMesh& in, VertexColourEncoding encoding) {
  Mesh out;
  out.positions.reserve(in.mNumVertices + 1);
  for (unsigned i = 0; i < in.mNumVertices; ++i)
    out.positions.push_back({in.mVertices[i].x, in.mVertices[i].y, in.mVertices[i].z});
  if (in.HasNormals()) {
    for (unsigned i = 0; i < in.mNumVertices; ++i)
      out.normals.push_back({in.mNormals[i].x, in.mNormals[i].y, in.mNormals[i].z});
  }
  if (in.HasTextureCoords(0)) {
    for (unsigned i = 0; i < in.mNumVertices; ++i)
      out.uvs.push_back({in.mTextureCoords[0][i].x, in.mTextureCoords[0][i].y});
  }
  if (in.HasVertexColors(0)) {
    for (unsigned i = 0; i < in.mNumVertices; ++i) {
      const aiColor4D& c = in.mColors[0][i];
      Vec3 rgb{c.r, c.g, c.b};
      if (encoding == VertexColourEncoding::Srgb)
        rgb = {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
      out.colours.push_back(rgb);
    }
  }
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left over
    out.indices.insert(out.indices.end(), face.mIndices, face.mIndices + 3);
  }
  return out;
}

// Gives each triangle its own three vertices with the face normal (flat shading in a mesh that
// otherwise carries vertex normals).
void make_faceted(Mesh& mesh) {
  Mesh flat;
  flat.positions.reserve(mesh.indices.size() + 1);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t* corner = &mesh.indices[3 * t];
    const Vec3 n = cross(mesh.positions[corner[1]] - mesh.positions[corner[0]],
                         mesh.positions[corner[2]] - mesh.positions[corner[0]]);
    const Vec3 unit_n = dot(n, n) > 0.0f ? normalize(n) : Vec3{0, 0, 1};
    for (int k = 0; k < 3; ++k) {
      flat.indices.push_back(static_cast<uint32_t>(flat.positions.size()));
      flat.positions.push_back(mesh.positions[corner[k]]);
      flat.normals.push_back(unit_n);
      if (!mesh.uvs.empty()) flat.uvs.push_back(mesh.uvs[corner[k]]);
      if (!mesh.colours.empty()) flat.colours.push_back(mesh.colours[corner[k]]);
    }
  }
  mesh.positions = std::move(flat.positions);
  mesh.indices = std::move(flat.indices);
  mesh.normals = std::move(flat.normals);
  mesh.uvs = std::move(flat.uvs);
  mesh.colours = std::move(flat.colours);
}

struct ImportContext {
  const aiScene& scene;
  const Transform& to_world;
  VertexColourEncoding encoding;
  const std::string& where;                       // the file, for error messages
  std::optional<std::string>& precision_warning;  // the first part whose file coordinates lose detail
};

// Collects every (mesh, node-to-world) instance of the node hierarchy, in world space, and the index of
// each one's material in the file.
void collect_parts(const ImportContext& context, const aiNode& node, const Transform& parent,
                   std::vector<Mesh>& parts, std::vector<unsigned>& materials) {
  const Transform global = parent * to_transform(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& source = *context.scene.mMeshes[node.mMeshes[i]];
    Mesh part = convert_mesh(source, context.encoding);
    if (part.indices.empty()) continue;
    part.validate(
        fmt::format("{}: mesh '{}' of node '{}'", context.where, source.mName.C_Str(), node.mName.C_Str()));
    if (!context.precision_warning)
      context.precision_warning = float_detail_warning(context.where, part.positions, part.indices);
    try {
      part.transform(context.to_world * global);
    } catch (const std::invalid_argument& e) {
      throw InputError(
          fmt::format("{}: node '{}' has a singular transform", context.where, node.mName.C_Str()));
    }
    parts.push_back(std::move(part));
    materials.push_back(source.mMaterialIndex);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    collect_parts(context, *node.mChildren[c], global, parts, materials);
}

template <typename T>
void append(std::vector<T>& dst, const std::vector<T>& src, size_t vertex_count, bool wanted, const T& fill) {
  if (!wanted) return;
  if (src.empty()) {
    dst.insert(dst.end(), vertex_count, fill);
  } else {
    dst.insert(dst.end(), src.begin(), src.end());
  }
}

Mesh merge_parts(std::vector<Mesh>& parts) {
  auto any = [&](auto member) {
    return std::any_of(parts.begin(), parts.end(), [&](const Mesh& m) { return !(m.*member).empty(); });
  };
  const bool has_normals = any(&Mesh::normals), has_uvs = any(&Mesh::uvs), has_colours = any(&Mesh::colours);
  size_t vertex_total = 1, index_total = 0;
  for (Mesh& part : parts) {
    if (has_normals && part.normals.empty()) make_faceted(part);
    vertex_total += part.positions.size();
    index_total += part.indices.size();
  }
  Mesh merged;
  merged.positions.reserve(vertex_total);  // + 1 spare position for Accel
  merged.indices.reserve(index_total);
  for (const Mesh& part : parts) {
    const auto base = static_cast<uint32_t>(merged.positions.size());
    for (uint32_t index : part.indices) merged.indices.push_back(base + index);
    merged.positions.insert(merged.positions.end(), part.positions.begin(), part.positions.end());
    append(merged.normals, part.normals, part.positions.size(), has_normals, Vec3{0, 0, 1});
    append(merged.uvs, part.uvs, part.positions.size(), has_uvs, Vec2{0, 0});
    append(merged.colours, part.colours, part.positions.size(), has_colours, Vec3{1, 1, 1});
  }
  return merged;
}

}  // namespace

float srgb_to_linear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

VertexColourEncoding vertex_colour_encoding(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  if (ext == ".ply") return ply_colour_encoding(file);
  if (ext == ".obj") return VertexColourEncoding::Srgb;
  return VertexColourEncoding::Linear;
}

namespace {

// The texture files a material of the file names, by their MTL keyword (glTF base colour maps are
// diffuse maps in Assimp, so they appear as map_Kd too).
std::map<std::string, std::string> material_textures(const aiMaterial& material) {
  static const std::pair<aiTextureType, const char*> kKeys[] = {
      {aiTextureType_DIFFUSE, "map_Kd"}, {aiTextureType_SPECULAR, "map_Ks"},
      {aiTextureType_AMBIENT, "map_Ka"}, {aiTextureType_SHININESS, "map_Ns"},
      {aiTextureType_OPACITY, "map_d"},  {aiTextureType_HEIGHT, "map_bump"},
      {aiTextureType_NORMALS, "norm"}};
  std::map<std::string, std::string> textures;
  for (const auto& [type, key] : kKeys) {
    aiString path;
    if (material.GetTextureCount(type) > 0 && material.GetTexture(type, 0, &path) == AI_SUCCESS)
      textures[key] = path.C_Str();
  }
  return textures;
}

// The file read with the importer's flags, its triangles collected per part with the part's material.
struct ImportedParts {
  Assimp::Importer importer;
  const aiScene* scene = nullptr;
  std::vector<Mesh> parts;
  std::vector<unsigned> materials;
  std::optional<std::string> precision_warning;  // float_detail_warning of the file's coordinates
};

void import_parts(ImportedParts& out, const std::filesystem::path& file, const Transform& to_world,
                  const MeshImportOptions& options) {
  // Points and lines pass through and are skipped by convert_mesh, so a file without triangles
  // gets our own error message rather than one from Assimp's validation.
  unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices;
  if (options.smooth_normals) flags |= aiProcess_GenSmoothNormals;
  if (options.flip_uv_v) flags |= aiProcess_FlipUVs;
  if (options.face_normals) flags |= aiProcess_DropNormals;
  out.scene = read_mesh_file(out.importer, file, flags);
  if (out.scene->mRootNode != nullptr) {
    const std::string where = file.string();
    const ImportContext context{*out.scene, to_world, vertex_colour_encoding(file), where,
                                out.precision_warning};
    collect_parts(context, *out.scene->mRootNode, Transform::identity(), out.parts, out.materials);
  }
  if (out.parts.empty()) throw InputError(fmt::format("{}: the file contains no triangles", file.string()));
}

}  // namespace

Mesh import_mesh(const std::filesystem::path& file, const Transform& to_world,
                 const MeshImportOptions& options, std::vector<std::string>* warnings) {
  ImportedParts imported;
  import_parts(imported, file, to_world, options);
  if (warnings && imported.precision_warning) warnings->push_back(*imported.precision_warning);
  Mesh mesh = merge_parts(imported.parts);
  mesh.name = file.stem().string();
  mesh.validate(file.string());
  return mesh;
}

std::vector<MeshMaterialPart> import_mesh_by_material(const std::filesystem::path& file,
                                                      const Transform& to_world,
                                                      const MeshImportOptions& options,
                                                      std::vector<std::string>* warnings) {
  ImportedParts imported;
  import_parts(imported, file, to_world, options);
  if (warnings && imported.precision_warning) warnings->push_back(*imported.precision_warning);
  std::vector<MeshMaterialPart> result;
  for (unsigned m = 0; m < imported.scene->mNumMaterials; ++m) {
    std::vector<Mesh> group;
    for (size_t i = 0; i < imported.parts.size(); ++i)
      if (imported.materials[i] == m) group.push_back(std::move(imported.parts[i]));
    if (group.empty()) continue;
    const aiMaterial& material = *imported.scene->mMaterials[m];
    MeshMaterialPart part;
    part.material = material.GetName().C_Str();
    part.textures = material_textures(material);
    part.mesh = merge_parts(group);
    part.mesh.name = file.stem().string() + "/" + part.material;
    part.mesh.validate(file.string());
    result.push_back(std::move(part));
  }
  return result;
}

}  // namespace ochre
