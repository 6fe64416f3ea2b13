#include "renderer/assimp_reader.h"

#include <fmt/format.h>

#include <fstream>
#include <string>

#include "renderer/input_error.h"

namespace ochre {

namespace {

// The line without the '\r' of a CRLF file.
std::string without_cr(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

// Assimp's PLY reader is chosen by content as well as by extension: any file whose first line is "ply".
void check_ply_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || without_cr(line) != "ply") return;
  while (std::getline(in, line))
    if (without_cr(line).starts_with("end_header")) return;
  throw InputError(fmt::format("{}: malformed PLY header: no end_header line", file.string()));
}

void check_faces(const aiScene& scene, const std::string& where) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices == 0)
        throw InputError(fmt::format("{}: mesh '{}': face {} has no vertices", where, mesh.mName.C_Str(), f));
      for (unsigned i = 0; i < face.mNumIndices; ++i)
        if (face.mIndices[i] >= mesh.mNumVertices)
          throw InputError(fmt::format("{}: mesh '{}': face {} uses vertex {}, but there are {} vertices",
                                       where, mesh.mName.C_Str(), f, face.mIndices[i], mesh.mNumVertices));
    }
  }
}

}  // namespace

const aiScene& read_with_assimp(Assimp::Importer& importer, const std::filesystem::path& file,
                                unsigned flags) {
  const std::string where = file.string();
  check_ply_header(file);
  const aiScene* scene = importer.ReadFile(where, 0);
  if (scene == nullptr)
    throw InputError(fmt::format("{}: cannot import mesh: {}", where, importer.GetErrorString()));
  check_faces(*scene, where);
  scene = importer.ApplyPostProcessing(flags);
  if (scene == nullptr)
    throw InputError(fmt::format("{}: cannot import mesh: {}", where, importer.GetErrorString()));
  return *scene;
}

}  // namespace ochre
