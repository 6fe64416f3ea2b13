#include "renderer/shapes/assimp_reader.h"

#include <fmt/format.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "spectra/input_error.h"

namespace ochre {

namespace {

// The line without the '\r' of a CRLF file.
std::string without_cr(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

bool is_ply_type(const std::string& word) {
  static const std::set<std::string> kTypes = {"char",  "uchar",  "short",   "ushort", "int",   "uint",
                                               "float", "double", "int8",    "uint8",  "int16", "uint16",
                                               "int32", "uint32", "float32", "float64"};
  return kTypes.contains(word);
}

bool is_count(const std::string& word) {
  return !word.empty() && word.size() <= 10 && word.find_first_not_of("0123456789") == std::string::npos;
}

// Why a PLY header line is malformed, or empty when it is well formed (P. Bourke, "PLY - Polygon File
// Format"): format, comment / obj_info, element NAME COUNT, property TYPE NAME, property list TYPE TYPE NAME.
std::string ply_header_line_fault(const std::vector<std::string>& w, bool& format_seen, bool& element_seen) {
  if (w.empty()) return "empty line";
  if (w[0] == "comment" || w[0] == "obj_info") return {};
  if (w[0] == "format") {
    if (format_seen) return "a second format line";
    format_seen = true;
    const bool known =
        w.size() == 3 && (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian");
    return known && w[2] == "1.0" ? "" : "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'";
  }
  if (!format_seen) return "expected the format line";
  if (w[0] == "element") {
    element_seen = true;
    return w.size() == 3 && is_count(w[2]) ? "" : "expected 'element NAME COUNT'";
  }
  if (w[0] == "property") {
    if (!element_seen) return "a property before any element";
    if (w.size() == 3 && is_ply_type(w[1])) return {};
    if (w.size() == 5 && w[1] == "list" && is_ply_type(w[2]) && is_ply_type(w[3])) return {};
    return "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'";
  }
  return "unknown keyword '" + w[0] + "'";
}

}  // namespace

void check_ply_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  const bool named_ply = file.extension() == ".ply" || file.extension() == ".PLY";
  if (!std::getline(in, line) || (!named_ply && !line.starts_with("ply"))) return;
  const std::string where = file.string();
  if (words_of(without_cr(line)) != std::vector<std::string>{"ply"})
    throw InputError(fmt::format("{}: malformed PLY header: the first line must be 'ply'", where));
  bool format_seen = false, element_seen = false;
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string> words = words_of(without_cr(line));
    if (words.size() == 1 && words[0] == "end_header") return;
    const std::string fault = ply_header_line_fault(words, format_seen, element_seen);
    if (!fault.empty())
      throw InputError(fmt::format("{}: malformed PLY header: line {}: {}", where, number, fault));
  }
  throw InputError(fmt::format("{}: malformed PLY header: no end_header line", where));
}

void check_mesh_faces(const aiScene& scene, const std::string& where) {
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

}  // namespace ochre
