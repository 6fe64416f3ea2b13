#pragma once
// `ochre render`: loads a scene, renders it, writes the outputs. Returns the process exit code:
// 0 success, 2 bad input or a request larger than the memory limit (nothing written), 1 internal error.

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/scene_loader.h"

namespace ochre {

struct RenderCommand {
  std::string scene;
  std::string exr, png;  // override the scene's outputs (relative to the working directory)
  SceneOverrides overrides;
  std::optional<std::string> ocio_config, display, view, colorspace;
  std::optional<float> exposure;
  bool quiet = false;
  bool aovs = false;
  int spectral_bins = 0;
  bool stokes = false;                        // Stokes layers in the EXR
  std::string polarization_png;               // false-colour DoLP / AoLP PNG
  std::optional<std::uint64_t> memory_limit;  // bytes (--memory-limit); default: the machine's memory
  // A frame sequence (docs/cli.md#frame-sequences): frames first_frame .. first_frame + frames - 1 at fps
  // frames per second, each written to the output names with the frame number inserted.
  std::optional<std::uint64_t> frames;
  std::uint64_t first_frame = 1;
  double fps = 24.0;
};

int run_render(const RenderCommand& command);

}  // namespace ochre
