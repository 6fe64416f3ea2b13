#include "renderer/shapes/displacement.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "spectra/input_error.h"

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

// Heights from the texture at each vertex's uv.
std::vector<float> texture_heights(const Mesh& mesh, const DisplacementOptions& options,
                                   OiioTextureProvider& textures) {
  if (mesh.uvs.empty())
    throw InputError(fmt::format("{}: displacement needs texture coordinates (uv)", mesh.name));
  int channels = 0, texture = 0;
  try {
    texture = textures.add_texture(options.file, options.colorspace, channels);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}: displacement: {}", mesh.name, e.what()));
  }
  std::vector<float> heights(mesh.positions.size());
  for (size_t i = 0; i < heights.size(); ++i) textures.lookup(texture, mesh.uvs[i], 0.0f, 0, 1, &heights[i]);
  return heights;
}

// Heights of the procedural rock at each vertex's position (a pure function: evaluated in parallel,
// the same result for any thread count).
std::vector<float> noise_heights(const Mesh& mesh, const RockNoise& noise, const Vec3d& origin) {
  std::vector<float> heights(mesh.positions.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, heights.size(), 4096), [&](const auto& range) {
    for (size_t i = range.begin(); i < range.end(); ++i)
      heights[i] = rock_height((Vec3d(mesh.positions[i]) + origin).to_float(), noise);
  });
  return heights;
}

}  // namespace

void displace(Mesh& mesh, const DisplacementOptions& options, OiioTextureProvider& textures,
              const Vec3d& origin) {
  if (mesh.normals.size() != mesh.positions.size())
    throw InputError(fmt::format("{}: displacement needs vertex normals", mesh.name));
  const std::vector<float> heights =
      options.noise ? noise_heights(mesh, *options.noise, origin) : texture_heights(mesh, options, textures);
  const std::vector<uint32_t> group = coincident_groups(mesh.positions);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    // A procedural height is the same for every copy of a vertex: moving the copies along one normal
    // keeps a seam closed. A texture may differ across a seam anyway (see displacement.h).
    const Vec3& n = options.noise ? mesh.normals[group[i]] : mesh.normals[i];
    mesh.positions[i] += n * (options.scale * (heights[i] - options.offset));
  }
  mesh.normals = area_weighted_normals(mesh, group);
  mesh.validate(mesh.name);
}

namespace {

// "noise": {...}: the parameters of rock_height() (docs/scene-format.md, shapes).
RockNoise parse_rock_noise(const JsonFields& f) {
  f.check_known({"frequency", "octaves", "lacunarity", "gain", "seed", "cracks", "crack_frequency",
                 "crack_width", "flowstone", "flowstone_frequency", "up"});
  RockNoise n;
  auto positive = [&](const char* key, float fallback) {
    return static_cast<float>(f.number(key, fallback, 0.0, 1e6, true));
  };
  n.frequency = positive("frequency", n.frequency);
  n.fractal.octaves = static_cast<int>(f.integer("octaves", n.fractal.octaves, 1, 16));
  n.fractal.lacunarity = static_cast<float>(f.number("lacunarity", n.fractal.lacunarity, 1.0, 8.0));
  n.fractal.gain = static_cast<float>(f.number("gain", n.fractal.gain, 0.0, 1.0));
  n.seed = static_cast<uint32_t>(f.integer("seed", 0, 0, 0xffffffffLL));
  n.cracks = static_cast<float>(f.number("cracks", n.cracks, 0.0, 1e6));
  n.crack_frequency = positive("crack_frequency", n.crack_frequency);
  n.crack_width = static_cast<float>(f.number("crack_width", n.crack_width, 0.0, 1.0, true));
  n.flowstone = static_cast<float>(f.number("flowstone", n.flowstone, 0.0, 1e6));
  n.flowstone_frequency = positive("flowstone_frequency", n.flowstone_frequency);
  const Vec3 up = f.vec3("up", n.up);
  if (!(length(up) > 0.0f) || !std::isfinite(length(up)))
    f.fail("up", "must be a non-zero vector of finite length");
  n.up = normalize(up);
  return n;
}

}  // namespace

DisplacementOptions parse_displacement(const JsonFields& fields, const std::filesystem::path& scene_dir) {
  fields.check_known({"file", "noise", "colorspace", "scale", "offset"});
  DisplacementOptions options;
  if (fields.has("file") == fields.has("noise"))
    fields.fail("", "give exactly one of \"file\" (a height texture) or \"noise\" (procedural rock)");
  if (fields.has("file")) options.file = scene_dir / fields.required_string("file");
  if (fields.has("noise"))
    options.noise = parse_rock_noise(JsonFields(fields.require("noise"), fields.child("noise")));
  options.colorspace = fields.string("colorspace", options.colorspace);
  if (options.colorspace != "linear" && options.colorspace != "srgb" && options.colorspace != "auto")
    fields.fail("colorspace",
                fmt::format("unknown colorspace '{}' (expected linear, srgb or auto)", options.colorspace));
  options.scale = static_cast<float>(fields.number("scale", options.scale));
  options.offset = static_cast<float>(fields.number("offset", options.offset));
  return options;
}

}  // namespace ochre
