#include "renderer/geometry/ply_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"

namespace ochre {

namespace {

static_assert(std::endian::native == std::endian::little, "the PLY writer writes the machine's byte order");

void append(std::string& bytes, const void* data, size_t size) {
  bytes.append(static_cast<const char*>(data), size);
}

void append_float(std::string& bytes, float v) {
  append(bytes, &v, sizeof v);
}

// Linear [0, 1] to an 8-bit sRGB code (IEC 61966-2-1 transfer function).
uint8_t srgb_byte(float linear) {
  const float c = std::clamp(std::isfinite(linear) ? linear : 0.0f, 0.0f, 1.0f);
  const float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(encoded * 255.0f));
}

std::string header(const Mesh& mesh) {
  std::string h = fmt::format(
      "ply\nformat binary_little_endian 1.0\ncomment written by ochre: {}\n"
      "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n",
      mesh.name.empty() ? "a mesh" : mesh.name, mesh.vertex_count());
  if (!mesh.normals.empty()) h += "property float nx\nproperty float ny\nproperty float nz\n";
  if (!mesh.uvs.empty()) h += "property float s\nproperty float t\n";
  if (!mesh.colours.empty()) h += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  h += fmt::format("element face {}\nproperty list uchar int vertex_indices\nend_header\n",
                   mesh.triangle_count());
  return h;
}

}  // namespace

void write_ply(const Mesh& mesh, const Vec3d& offset, const std::filesystem::path& path) {
  std::string bytes = header(mesh);
  const size_t vertex_bytes =
      12 + (mesh.normals.empty() ? 0 : 12) + (mesh.uvs.empty() ? 0 : 8) + (mesh.colours.empty() ? 0 : 3);
  bytes.reserve(bytes.size() + mesh.vertex_count() * vertex_bytes + mesh.triangle_count() * 13);
  for (size_t i = 0; i < mesh.vertex_count(); ++i) {
    const Vec3 p = (offset + Vec3d(mesh.positions[i])).to_float();
    for (float v : {p.x, p.y, p.z}) append_float(bytes, v);
    if (!mesh.normals.empty())
      for (float v : {mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z}) append_float(bytes, v);
    if (!mesh.uvs.empty())
      for (float v : {mesh.uvs[i].x, mesh.uvs[i].y}) append_float(bytes, v);
    if (!mesh.colours.empty())
      for (float v : {mesh.colours[i].x, mesh.colours[i].y, mesh.colours[i].z})
        bytes.push_back(char(srgb_byte(v)));
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    bytes.push_back(char(3));
    for (int k = 0; k < 3; ++k) {
      const int32_t index = static_cast<int32_t>(mesh.indices[3 * t + k]);
      append(bytes, &index, sizeof index);
    }
  }
  AtomicOutput output(path);
  {
    std::ofstream out(output.temp_path(), std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw ImageError(fmt::format("cannot write {}: {}", path.string(), std::strerror(errno)));
  }
  output.commit();
}

}  // namespace ochre
