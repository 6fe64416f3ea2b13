#pragma once
// `ochre relight RENDER.exr --group NAME:scale=S|off|on ... -o OUT.exr [--png OUT.png] [--html DIR]`
// (docs/lights.md, "Relighting"): the render's image recombined from its light groups with new intensities,
// written as a render writes (the EXR, the display image through the render's display transform); and/or a
// page that relights the render in a browser (DIR/index.html, "Relighting page"). Returns the exit
// code; bad input throws (run_program: exit 2), nothing written.

#include <optional>
#include <string>
#include <vector>

namespace ochre {

struct RelightCommand {
  std::string render;               // the EXR of a render with light groups
  std::vector<std::string> groups;  // --group NAME:CHANGE
  std::string exr, png;
  std::string html;  // --html DIR: the relighting page
  bool quiet = false;
  std::optional<std::string> ocio_config, display, view;  // default: the render's
  std::optional<float> exposure;
};

int run_relight(const RelightCommand& command);

}  // namespace ochre
