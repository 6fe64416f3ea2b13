#include "renderer/shapes/control_mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

#include "renderer/shapes/float_detail.h"
#include "renderer/shapes/mesh_file_reader.h"
#include "renderer/shapes/mesh_import.h"
#include "renderer/util/ascii_case.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

// The faces as triangle fans (corner 0 with each later pair): enough for the edge lengths of
// float_detail_warning.
std::vector<uint32_t> fan_triangles(const std::vector<int>& face_sizes,
                                    const std::vector<int>& face_vertices) {
  std::vector<uint32_t> indices;
  size_t at = 0;
  for (const int size : face_sizes) {
    for (int k = 1; k + 1 < size; ++k)
      indices.insert(indices.end(),
                     {static_cast<uint32_t>(face_vertices[at]), static_cast<uint32_t>(face_vertices[at + k]),
                      static_cast<uint32_t>(face_vertices[at + k + 1])});
    at += static_cast<size_t>(size);
  }
  return indices;
}

// Exact bit pattern of a position: welding must only join vertices the file meant to be one.
struct PositionKey {
  uint32_t bits[3];
  explicit PositionKey(const Vec3& p) {
    const float values[3] = {p.x == 0.0f ? 0.0f : p.x, p.y == 0.0f ? 0.0f : p.y, p.z == 0.0f ? 0.0f : p.z};
    std::memcpy(bits, values, sizeof(bits));  // -0 and +0 weld together
  }
  bool operator==(const PositionKey& o) const { return std::equal(bits, bits + 3, o.bits); }
};
struct PositionKeyHash {
  size_t operator()(const PositionKey& k) const {
    return (size_t{k.bits[0]} * 73856093u) ^ (size_t{k.bits[1]} * 19349663u) ^
           (size_t{k.bits[2]} * 83492791u);
  }
};

// Face-varying uv value owned by one welded vertex (OpenSubdiv expects every value to belong to a
// single vertex).
struct UvKey {
  int vertex;
  uint32_t bits[2];
  bool operator==(const UvKey& o) const {
    return vertex == o.vertex && bits[0] == o.bits[0] && bits[1] == o.bits[1];
  }
};
struct UvKeyHash {
  size_t operator()(const UvKey& k) const {
    return size_t(k.vertex) * 2654435761u ^ (size_t{k.bits[0]} * 19349663u) ^ (size_t{k.bits[1]} * 83492791u);
  }
};

// Accumulates the welded control mesh while walking the Assimp node hierarchy.
class Welder {
 public:
  Welder(ControlMesh& out, VertexColourEncoding encoding) : out_(out), encoding_(encoding) {}

  void add_mesh(const aiMesh& in, const Transform& to_file) {
    std::vector<int> welded(in.mNumVertices);
    for (unsigned i = 0; i < in.mNumVertices; ++i) {
      const Vec3 p = to_file.point({in.mVertices[i].x, in.mVertices[i].y, in.mVertices[i].z});
      auto [it, inserted] = vertex_of_.try_emplace(PositionKey(p), static_cast<int>(out_.positions.size()));
      welded[i] = it->second;
      if (!inserted) continue;
      out_.positions.push_back(p);
      colours_.push_back(colour(in, i));
    }
    any_uvs_ = any_uvs_ || in.HasTextureCoords(0);
    any_colours_ = any_colours_ || in.HasVertexColors(0);
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      const std::vector<unsigned> corners = distinct_neighbour_corners(face, welded);
      if (corners.size() < 3) continue;  // points, lines, faces of no area
      if (!faces_.insert(canonical_cycle(corners, welded)).second) continue;  // a face given twice
      out_.face_sizes.push_back(static_cast<int>(corners.size()));
      for (const unsigned corner : corners) {
        out_.face_vertices.push_back(welded[corner]);
        const Vec2 uv = in.HasTextureCoords(0)
                            ? Vec2{in.mTextureCoords[0][corner].x, in.mTextureCoords[0][corner].y}
                            : Vec2{0, 0};
        out_.face_uv_indices.push_back(uv_index(welded[corner], uv));
      }
    }
  }

  void finish() {
    if (!any_uvs_) {
      out_.uvs.clear();
      out_.face_uv_indices.clear();
    }
    if (any_colours_) out_.colours = std::move(colours_);
  }

 private:
  Vec3 colour(const aiMesh& in, unsigned i) const {
    if (!in.HasVertexColors(0)) return {1, 1, 1};
    const aiColor4D& c = in.mColors[0][i];
    if (encoding_ == VertexColourEncoding::Srgb)
      return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
    return {c.r, c.g, c.b};
  }

  int uv_index(int vertex, const Vec2& uv) {
    UvKey key{vertex, {}};
    std::memcpy(key.bits, &uv.x, sizeof(float));
    std::memcpy(key.bits + 1, &uv.y, sizeof(float));
    auto [it, inserted] = uv_of_.try_emplace(key, static_cast<int>(out_.uvs.size()));
    if (inserted) out_.uvs.push_back(uv);
    return it->second;
  }

  // The face's corners without those welded onto the vertex of the corner before them (cyclically): an
  // edge of zero length, from a file that repeats a vertex or gives two corners the same position. The
  // face keeps its shape, and OpenSubdiv, which cannot refine such edges (it corrupts memory), never sees
  // them.
  static std::vector<unsigned> distinct_neighbour_corners(const aiFace& face,
                                                          const std::vector<int>& welded) {
    std::vector<unsigned> corners;
    corners.reserve(face.mNumIndices);
    for (unsigned k = 0; k < face.mNumIndices; ++k) {
      const unsigned corner = face.mIndices[k];
      if (corners.empty() || welded[corner] != welded[corners.back()]) corners.push_back(corner);
    }
    while (corners.size() > 1 && welded[corners.back()] == welded[corners.front()]) corners.pop_back();
    return corners;
  }

  ControlMesh& out_;
  VertexColourEncoding encoding_;
  // The welded vertex cycle of a face from its least vertex, in the direction whose second vertex is the
  // lesser: the same for a face written again from another corner or with the other winding.
  static std::vector<int> canonical_cycle(const std::vector<unsigned>& corners,
                                          const std::vector<int>& welded) {
    std::vector<int> cycle;
    for (const unsigned corner : corners) cycle.push_back(welded[corner]);
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    if (cycle.back() < cycle[1]) std::reverse(cycle.begin() + 1, cycle.end());
    return cycle;
  }

  // Faces met so far (canonical_cycle): a face given twice makes its edges meet four faces, a non-manifold
  // surface OpenSubdiv's limit evaluation cannot take (it corrupted memory; a fuzzing finding) and that
  // adds nothing to the surface.
  std::set<std::vector<int>> faces_;
  std::unordered_map<PositionKey, int, PositionKeyHash> vertex_of_;
  std::unordered_map<UvKey, int, UvKeyHash> uv_of_;
  std::vector<Vec3> colours_;
  bool any_uvs_ = false, any_colours_ = false;
};

void collect(const aiScene& scene, const aiNode& node, const Transform& parent, Welder& welder) {
  const Transform global = parent * to_transform(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i) welder.add_mesh(*scene.mMeshes[node.mMeshes[i]], global);
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], global, welder);
}

// One OpenSubdiv OBJ tag line: "t name ints/floats[/strings] ints... floats...".
struct ObjTag {
  std::string name;
  std::vector<long> ints;
  std::vector<float> floats;
  int line = 0;
};

ObjTag parse_tag(const std::string& text, int line, const std::string& where) {
  std::istringstream words(text);
  ObjTag tag;
  tag.line = line;
  std::string t, counts;
  words >> t >> tag.name >> counts;
  int nint = -1, nfloat = -1, nstring = 0;
  if (std::sscanf(counts.c_str(), "%d/%d/%d", &nint, &nfloat, &nstring) < 2 || nint < 0 || nfloat < 0 ||
      nstring != 0) {
    throw InputError(fmt::format("{}: line {}: malformed tag counts '{}' (expected ints/floats[/0])", where,
                                 line, counts));
  }
  tag.ints.resize(static_cast<size_t>(nint));
  tag.floats.resize(static_cast<size_t>(nfloat));
  for (long& v : tag.ints) words >> v;
  for (float& v : tag.floats) words >> v;
  if (!words)
    throw InputError(
        fmt::format("{}: line {}: tag '{}' has fewer values than announced", where, line, tag.name));
  return tag;
}

struct ObjExtras {
  std::vector<Vec3> v_lines;  // positions in "v" line order
  std::vector<ObjTag> tags;
};

ObjExtras read_obj_extras(const std::filesystem::path& file) {
  ObjExtras extras;
  InputFile input = InputFile::open(file, kMeshFileInput);
  const std::unique_ptr<std::istream> in = input.stream();
  std::string text;
  for (int line = 1; std::getline(*in, text); ++line) {
    if (text.size() < 2 || !std::isspace(static_cast<unsigned char>(text[1]))) continue;
    if (text[0] == 'v') {
      Vec3 p;
      std::istringstream(text.substr(1)) >> p.x >> p.y >> p.z;
      extras.v_lines.push_back(p);
    } else if (text[0] == 't') {
      ObjTag tag = parse_tag(text, line, file.string());
      if (tag.name == "crease" || tag.name == "corner") extras.tags.push_back(std::move(tag));
    }
  }
  return extras;
}

// Welded index of OBJ vertex `obj_index`: the exact position, else the nearest one (Assimp's number
// parser may round the last bit differently from ours).
int welded_index(const ControlMesh& mesh, const ObjExtras& extras, long obj_index, const ObjTag& tag,
                 const std::string& where) {
  if (obj_index < 0 || obj_index >= static_cast<long>(extras.v_lines.size())) {
    throw InputError(fmt::format("{}: line {}: tag '{}' vertex {} out of range (0..{})", where, tag.line,
                                 tag.name, obj_index, extras.v_lines.size()));
  }
  const Vec3 p = extras.v_lines[static_cast<size_t>(obj_index)];
  int best = -1;
  float best_distance = std::numeric_limits<float>::max();
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3 d = mesh.positions[i] - p;
    const float distance = dot(d, d);
    if (distance < best_distance) best = static_cast<int>(i), best_distance = distance;
    if (distance == 0.0f) break;
  }
  if (best < 0)
    throw InputError(
        fmt::format("{}: line {}: tag vertex {} is not used by any face", where, tag.line, obj_index));
  return best;
}

void apply_obj_tags(ControlMesh& mesh, const ObjExtras& extras, const std::string& where) {
  for (const ObjTag& tag : extras.tags) {
    if (tag.floats.size() != 1 || tag.ints.size() < (tag.name == "crease" ? 2u : 1u)) {
      throw InputError(fmt::format("{}: line {}: tag '{}' needs vertex indices and one sharpness", where,
                                   tag.line, tag.name));
    }
    const float sharpness = tag.floats[0];
    if (tag.name == "corner") {
      for (long v : tag.ints) {
        mesh.corner_vertices.push_back(welded_index(mesh, extras, v, tag, where));
        mesh.corner_sharpness.push_back(sharpness);
      }
      continue;
    }
    for (size_t k = 0; k + 1 < tag.ints.size(); ++k) {
      mesh.crease_edges.emplace_back(welded_index(mesh, extras, tag.ints[k], tag, where),
                                     welded_index(mesh, extras, tag.ints[k + 1], tag, where));
      mesh.crease_sharpness.push_back(sharpness);
    }
  }
}

void reverse_winding(ControlMesh& mesh) {
  size_t start = 0;
  for (int size : mesh.face_sizes) {
    std::reverse(mesh.face_vertices.begin() + long(start),
                 mesh.face_vertices.begin() + long(start + size_t(size)));
    if (!mesh.face_uv_indices.empty())
      std::reverse(mesh.face_uv_indices.begin() + long(start),
                   mesh.face_uv_indices.begin() + long(start + size_t(size)));
    start += size_t(size);
  }
}

}  // namespace

bool ControlMesh::all_triangles() const {
  return std::all_of(face_sizes.begin(), face_sizes.end(), [](int n) { return n == 3; });
}

namespace {

// A vertex that occurs twice among a face's corners, if any.
std::optional<int> repeated_vertex(const int* corners, size_t count) {
  constexpr size_t kSmallFace = 8;  // compared pairwise, without an allocation
  if (count <= kSmallFace) {
    for (size_t i = 1; i < count; ++i)
      for (size_t j = 0; j < i; ++j)
        if (corners[i] == corners[j]) return corners[i];
    return std::nullopt;
  }
  std::vector<int> sorted(corners, corners + count);
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice == sorted.end()) return std::nullopt;
  return *twice;
}

}  // namespace

void ControlMesh::validate(const std::string& where) const {
  auto fail = [&](const std::string& message) {
    throw InputError(fmt::format("{}: control mesh: {}", where, message));
  };
  if (face_sizes.empty()) fail("no faces");
  size_t corners = 0;
  for (size_t f = 0; f < face_sizes.size(); ++f) {
    if (face_sizes[f] < 3) fail(fmt::format("face {} has {} vertices (at least 3 needed)", f, face_sizes[f]));
    corners += size_t(face_sizes[f]);
  }
  if (face_vertices.size() != corners)
    fail(fmt::format("{} face vertices for {} corners", face_vertices.size(), corners));
  for (size_t i = 0; i < positions.size(); ++i)
    if (!is_finite(positions[i])) fail(fmt::format("position {} is not finite", i));
  for (int v : face_vertices)
    if (v < 0 || size_t(v) >= positions.size()) fail(fmt::format("face vertex index {} out of range", v));
  size_t first = 0;
  for (size_t f = 0; f < face_sizes.size(); first += size_t(face_sizes[f]), ++f) {
    if (const std::optional<int> v = repeated_vertex(&face_vertices[first], size_t(face_sizes[f])))
      fail(
          fmt::format("face {} (of the welded polygons) passes through vertex {} at ({}, {}, {}) twice "
                      "(OpenSubdiv cannot refine a face that touches itself or has an edge of zero length)",
                      f, *v, positions[size_t(*v)].x, positions[size_t(*v)].y, positions[size_t(*v)].z));
  }
  if (!uvs.empty() || !face_uv_indices.empty()) {
    if (face_uv_indices.size() != corners)
      fail(fmt::format("{} uv indices for {} corners", face_uv_indices.size(), corners));
    for (int u : face_uv_indices)
      if (u < 0 || size_t(u) >= uvs.size()) fail(fmt::format("uv index {} out of range", u));
    for (size_t i = 0; i < uvs.size(); ++i)
      if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y)) fail(fmt::format("uv {} is not finite", i));
  }
  if (!colours.empty() && colours.size() != positions.size()) fail("colours and positions differ in count");
  for (size_t i = 0; i < colours.size(); ++i)
    if (!is_finite(colours[i])) fail(fmt::format("colour {} is not finite", i));
  if (crease_edges.size() != crease_sharpness.size()) fail("crease edges and sharpness differ in count");
  for (size_t i = 0; i < crease_edges.size(); ++i) {
    const auto [a, b] = crease_edges[i];
    if (a < 0 || b < 0 || size_t(a) >= positions.size() || size_t(b) >= positions.size())
      fail(fmt::format("crease {} vertex out of range", i));
    if (!(crease_sharpness[i] >= 0.0f) || std::isnan(crease_sharpness[i]))
      fail(fmt::format("crease {} sharpness must be >= 0", i));
  }
  if (corner_vertices.size() != corner_sharpness.size())
    fail("corner vertices and sharpness differ in count");
  for (size_t i = 0; i < corner_vertices.size(); ++i) {
    if (corner_vertices[i] < 0 || size_t(corner_vertices[i]) >= positions.size())
      fail(fmt::format("corner {} vertex out of range", i));
    if (!(corner_sharpness[i] >= 0.0f)) fail(fmt::format("corner {} sharpness must be >= 0", i));
  }
}

ControlMesh import_control_mesh(const std::filesystem::path& file, const Transform& to_world,
                                std::vector<std::string>* warnings) {
  const std::string where = file.string();
  Assimp::Importer importer;
  const aiScene* scene = read_mesh_file(importer, file, aiProcess_JoinIdenticalVertices);
  ControlMesh mesh;
  mesh.name = file.stem().string();
  Welder welder(mesh, vertex_colour_encoding(file));
  if (scene->mRootNode != nullptr) collect(*scene, *scene->mRootNode, Transform::identity(), welder);
  welder.finish();
  if (mesh.face_sizes.empty())
    throw InputError(
        fmt::format("{}: the file contains no polygons (faces of at least 3 distinct vertices)", where));
  if (lower_extension(file) == ".obj") apply_obj_tags(mesh, read_obj_extras(file), where);
  mesh.validate(where);  // before the transform: messages give the file's own coordinates
  if (warnings)
    if (const auto warning =
            float_detail_warning(where, mesh.positions, fan_triangles(mesh.face_sizes, mesh.face_vertices)))
      warnings->push_back(*warning);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    mesh.positions[i] = to_world.point(mesh.positions[i]);
    if (!is_finite(mesh.positions[i]))
      throw InputError(fmt::format("{}: the transform takes vertex {} beyond single precision", where, i));
  }
  if (to_world.flips_handedness()) reverse_winding(mesh);
  return mesh;
}

ControlMesh quad_grid_control_mesh(int nx, int ny) {
  ControlMesh mesh;
  mesh.name = "grid";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(nx),
                  v = static_cast<float>(j) / static_cast<float>(ny);
      mesh.positions.push_back({2 * u - 1, v, 0});
      mesh.uvs.push_back({u, v});
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      mesh.face_sizes.push_back(4);
      mesh.face_vertices.insert(mesh.face_vertices.end(), {a, a + 1, a + nx + 2, a + nx + 1});
    }
  mesh.face_uv_indices = mesh.face_vertices;
  return mesh;
}

}  // namespace ochre
