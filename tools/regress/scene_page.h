#pragma once
// The page of one scene in an HTML report (docs/tools.md, "HTML report"): the test result and metrics;
// reference, new render, Delta E00 and z-score images side by side, or reference and new under a slider
// or a flip toggle, zoomable to single pixels with the failing pixels marked (report.js); the values of
// the pixel under the cursor and, with spectral layers, its spectrum. Without JavaScript the images and
// numbers are still there.

#include <string>

#include "tools/regress/pixel_grid.h"
#include "tools/regress/report_images.h"
#include "tools/regress/scene_report.h"

namespace ochre {

struct ScenePageLinks {
  std::string data_script;                                         // <name>.data.js
  std::string previous_page, previous_name, next_page, next_name;  // "" at the ends
};

std::string scene_page(const SceneReport& report, const SceneImageFiles& images, const PixelGrid& grid,
                       const ScenePageLinks& links);

}  // namespace ochre
