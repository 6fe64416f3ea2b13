#pragma once
// Displacement mapping of a (subdivided) triangle mesh by a height texture.

#include <filesystem>
#include <optional>
#include <string>

#include "materials/numerics/noise.h"
#include "renderer/geometry/mesh.h"
#include "renderer/json/json_fields.h"
#include "renderer/texture/texture_system.h"

namespace ochre {

struct DisplacementOptions {
  std::filesystem::path file;         // height texture (channel 0 is used), unless `noise` is set
  std::string colorspace = "linear";  // how the file is encoded: "linear", "srgb" or "auto"
  float scale = 1.0f;
  float offset = 0.0f;
  std::optional<RockNoise> noise = std::nullopt;  // a procedural height field of the world position
};

// Moves every vertex along its shading normal: p += n * scale * (h - offset), where h is channel 0 of
// the texture at the vertex uv (finest MIP level, bilinear) or, with `noise`, rock_height() of the
// vertex's world position (no uvs needed; every copy of a vertex gets the same height and moves along
// the same normal, so seams stay closed), then replaces the normals
// by the area-weighted normals of the displaced triangles. Vertices at the same position (the two
// sides of a uv seam) share one normal, so seams do not show in the shading; they are displaced
// with their own uv, so a texture that does not match across a seam opens a crack there.
// Throws InputError starting with mesh.name when the mesh has no uvs or no normals, or naming the
// file when the texture cannot be read.
// `origin`: where the mesh's coordinates start in the scene (the rendering origin, renderer/scene/scene.h):
// procedural rock is a function of the world position origin + p.
void displace(Mesh& mesh, const DisplacementOptions& options, OiioTextureProvider& textures,
              const Vec3d& origin = {});

// {"file": path (relative to scene_dir), "colorspace": "linear" | "srgb" | "auto", "scale": s,
//  "offset": o} or {"noise": {...}, "scale": s, "offset": o} (docs/scene-format.md); exactly one of
// "file" and "noise"; unknown members are errors.
DisplacementOptions parse_displacement(const JsonFields& fields, const std::filesystem::path& scene_dir);

}  // namespace ochre
