#include "renderer/displacement.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "renderer/input_error.h"

namespace ochre {

namespace {

// Groups vertices at exactly the same position (the copies a uv seam creates): group[i] is the
// index of the first vertex at the position of vertex i.
std::vector<uint32_t> coincident_groups(const std::vector<Vec3>& positions) {
  struct KeyHash {
    size_t operator()(const std::array<uint32_t, 3>& k) const {
      return (size_t{k[0]} * 73856093u) ^ (size_t{k[1]} * 19349663u) ^ (size_t{k[2]} * 83492791u);
    }
  };
  std::unordered_map<std::array<uint32_t, 3>, uint32_t, KeyHash> first;
  first.reserve(positions.size());
  std::vector<uint32_t> group(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    std::array<uint32_t, 3> key;
    std::memcpy(key.data(), &positions[i], sizeof(key));
    group[i] = first.try_emplace(key, static_cast<uint32_t>(i)).first->second;
  }
  return group;
}

// Area-weighted vertex normals (the cross product of two edges is twice the area times the unit
// normal), accumulated per group of coincident vertices.
std::vector<Vec3> area_weighted_normals(const Mesh& mesh, const std::vector<uint32_t>& group) {
  std::vector<Vec3> sum(mesh.positions.size());
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    const Vec3 n =
        cross(mesh.positions[v[1]] - mesh.positions[v[0]], mesh.positions[v[2]] - mesh.positions[v[0]]);
    for (int k = 0; k < 3; ++k) sum[group[v[k]]] += n;
  }
  std::vector<Vec3> normals(mesh.positions.size());
  for (size_t i = 0; i < normals.size(); ++i) {
    const Vec3& n = sum[group[i]];
    normals[i] = dot(n, n) > 0.0f ? normalize(n) : mesh.normals[i];  // keep the old one if degenerate
  }
  return normals;
}

}  // namespace

void displace(Mesh& mesh, const DisplacementOptions& options, OiioTextureProvider& textures) {
  if (mesh.uvs.empty())
    throw InputError(fmt::format("{}: displacement needs texture coordinates (uv)", mesh.name));
  if (mesh.normals.size() != mesh.positions.size())
    throw InputError(fmt::format("{}: displacement needs vertex normals", mesh.name));
  int channels = 0, texture = 0;
  try {
    texture = textures.add_texture(options.file, options.colorspace, channels);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}: displacement: {}", mesh.name, e.what()));
  }
  const std::vector<uint32_t> group = coincident_groups(mesh.positions);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    float height = 0.0f;
    textures.lookup(texture, mesh.uvs[i], 0.0f, 0, 1, &height);
    mesh.positions[i] += mesh.normals[i] * (options.scale * (height - options.offset));
  }
  mesh.normals = area_weighted_normals(mesh, group);
  mesh.validate(mesh.name);
}

DisplacementOptions parse_displacement(const JsonFields& fields, const std::filesystem::path& scene_dir) {
  fields.check_known({"file", "colorspace", "scale", "offset"});
  DisplacementOptions options;
  options.file = scene_dir / fields.required_string("file");
  options.colorspace = fields.string("colorspace", options.colorspace);
  if (options.colorspace != "linear" && options.colorspace != "srgb" && options.colorspace != "auto")
    fields.fail("colorspace",
                fmt::format("unknown colorspace '{}' (expected linear, srgb or auto)", options.colorspace));
  options.scale = static_cast<float>(fields.number("scale", options.scale));
  options.offset = static_cast<float>(fields.number("offset", options.offset));
  return options;
}

}  // namespace ochre
