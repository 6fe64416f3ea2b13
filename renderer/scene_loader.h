#pragma once
// Loads a JSON scene (docs/scene-format.md) into a Scene. Every problem in the file or in a
// file it names throws InputError with the file and the field at fault; nothing is rendered
// or written before the whole scene has loaded.

#include <filesystem>
#include <memory>

#include "renderer/scene.h"

namespace ochre {

struct SceneOverrides {
  std::optional<uint32_t> spp;
  std::optional<int> threads;
  std::optional<uint64_t> seed;
  std::optional<int> width, height;
  std::optional<std::string> polarization;
  std::optional<std::string> sampler;
  std::optional<std::string> preset;  // a named variant from the scene's "presets" (docs/scene-format.md)
};

std::unique_ptr<Scene> load_scene(const std::filesystem::path& file, const SceneOverrides& overrides = {});

}  // namespace ochre
