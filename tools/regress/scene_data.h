#pragma once
// The pixel values of a scene page (<name>.data.js in an HTML report, docs/tools.md): a JavaScript file that
// sets window.ochreSceneData, loaded with a plain <script src> so that the page works from a file:// URL,
// where fetch() of local files is blocked. Values are base64 little-endian float32 arrays on a grid
// (tools/regress/pixel_grid.h) of at most kMaxSceneDataValues values:
//   reference.rgb, new.rgb   linear working-space RGB (3 per cell; block mean)
//   z                        z-score of the luminance test (the block's largest |z|)
//   nlp                      -log10 of the p-value (the block's largest)
//   failing                  failing pixels in the block
//   de00                     display-referred CIEDE2000 (block mean)
//   reference.stokes, new.stokes   Y-weighted S0..S3 (4 per cell), when the image has Stokes layers
//   spectral.reference, spectral.new  S0 radiance per spectral bin, when the image has spectral layers
// with rgbToXyz (the working space's matrix, row-major) for the XYZ readout.

#include <string>

#include "tools/regress/pixel_grid.h"
#include "tools/regress/scene_report.h"

namespace ochre {

inline constexpr size_t kMaxSceneDataValues = size_t{1} << 19;  // 2 MiB of floats per scene at most

// The script's text; grid receives the grid it used.
std::string scene_data_js(const SceneReport& report, PixelGrid& grid);

}  // namespace ochre
