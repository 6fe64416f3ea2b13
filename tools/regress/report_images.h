#pragma once
// The PNG images of an HTML report's scene page (docs/tools.md, "HTML report"): reference and new render
// through the scene's display transform, the display-referred Delta E00 between them, the z-scores of
// the luminance test, and small thumbnails of large images for the index.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/regress/scene_report.h"

namespace ochre {

// Full dark red of the Delta E00 heat map.
inline constexpr double kDe00FullScale = 10.0;
// The z heat map reaches its darkest colours at this many times the failure level (critical_z).
inline constexpr double kZFullScaleFactor = 2.0;
// Thumbnails are written for images larger than this (either side, pixels); smaller ones are shown as
// they are.
inline constexpr int kThumbnailSize = 160;

// Diverging colour of t in [-1, 1] (clamped; NaN -> black): dark blue (new darker than the reference)
// through white (agreement) to dark red (new brighter), 8-bit sRGB.
std::array<std::uint8_t, 3> diverging_colour(double t);

// The files of one scene, relative to the report directory.
struct SceneImageFiles {
  std::string reference, render, difference, z;
  std::string reference_thumbnail, render_thumbnail;  // = reference, render for small images
};

// Writes <prefix>.reference.png, .new.png, .difference.png, .z.png (and .thumb-*.png) into dir.
SceneImageFiles write_scene_images(const SceneReport& report, const std::filesystem::path& dir,
                                   const std::string& prefix);

}  // namespace ochre
