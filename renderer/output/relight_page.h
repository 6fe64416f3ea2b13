#pragma once
// The relighting page of `ochre relight RENDER.exr --html DIR` (docs/lights.md, "Relighting page"): one
// self-contained DIR/index.html (no external references; it works from a file:// URL) with a slider per
// light group for its intensity and, where the group has spectral bins and one emission spectrum, for its
// colour temperature; the relit display image is drawn in a canvas as the sliders move, and the page shows
// the `ochre relight` command that writes the same image.

#include <cstdint>
#include <filesystem>
#include <string>

#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"

namespace ochre {

// What the page holds, for the report and the docs' size table.
struct RelightPageStats {
  std::uintmax_t bytes = 0;  // of index.html
  int groups = 0;
  int cct_groups = 0;      // groups with a colour-temperature slider
  int basis_images = 0;    // over those groups (each an RGB image)
  int lattice_points = 0;  // per axis of the display lattice
};

// Throws InputError naming dir when the page cannot be written there: dir is empty, its parent is not a
// directory, or dir exists and is a symbolic link, not a directory, or a directory that is not empty.
void check_relight_page_destination(const std::filesystem::path& dir);

// Writes dir/index.html for the render `image` (read from `render`, the path the page's command names)
// through `display`, all or nothing: into a scratch directory beside dir that replaces it when complete.
// Checks dir first (check_relight_page_destination). InputError for a render without light groups (as
// relight()); ImageError when the display transform cannot be built or the directory written.
RelightPageStats write_relight_page(const ExrImage& image, const DisplayOptions& display,
                                    const std::string& render, const std::filesystem::path& dir);

}  // namespace ochre
