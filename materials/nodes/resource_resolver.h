#pragma once
// ResourceResolver: how the material compiler reaches files named in a scene. The renderer
// implements it (paths relative to the scene file, textures opened through OIIO); tests use a stub.

#include <filesystem>
#include <string>

namespace ochre {

class ResourceResolver {
 public:
  virtual ~ResourceResolver() = default;
  // Absolute path of a file named in the scene (relative paths are relative to the scene file).
  // No existence check.
  virtual std::filesystem::path resolve(const std::string& path) const = 0;
  // Opens a texture and returns its id and channel count; throws std::runtime_error(message) when
  // it cannot. colorspace is "auto", "srgb" or "linear" (the texture node's parameter).
  virtual int texture(const std::filesystem::path& file, const std::string& colorspace, int& channels) = 0;
};

}  // namespace ochre
