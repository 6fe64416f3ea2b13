#pragma once
// The training of a render's path guide (integrator.guiding; renderer/integrator/path_guide.h): unguided
// paths from a grid of pixels, about a tenth as many as the render traces, with numbers of their own seed,
// before the render (docs/architecture.md#path-guiding). The guide is a function of the scene and the
// render's settings alone (the whole render's: not of a part's sample range or pixel region, nor of the
// branches and roulette a pilot chooses), so every part, region and resumed piece of a render trains the
// same guide.

#include <memory>
#include <string>

#include "renderer/integrator/path_guide.h"
#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene.h"

namespace ochre {

struct GuideTraining {
  bool trained = false;
  double seconds = 0;
  uint64_t paths = 0;    // training paths traced
  uint64_t records = 0;  // scatterings observed
  size_t usable_cells = 0, cells = 0;
  std::string summary;  // one line for the render's summary
};

// The guide for a render of `scene` with `job`'s settings, or null where there is nothing to guide (no
// light, or paths of one vertex) or nothing was learned.
std::shared_ptr<const PathGuide> train_path_guide(const Scene& scene, const RenderJob& job,
                                                  GuideTraining* report = nullptr);

}  // namespace ochre
