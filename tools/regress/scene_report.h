#pragma once
// What an HTML report shows of one scene of an ochre-regress run (docs/tools.md, "HTML report"): the
// z-test result, the reference and the new render as EXR images (with their Stokes and spectral layers
// when the scene has them), the display transform of the scene's PNG output and the image metrics.

#include <optional>
#include <string>

#include "renderer/compare/image_metrics.h"
#include "renderer/compare/regression_compare.h"
#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"

namespace ochre {

struct SceneTiming {
  double seconds = 0.0;  // the render alone (not loading the scene)
  double spp = 0.0;
};

struct SceneReport {
  std::string name;
  std::string description;  // the scene file's description
  std::string message;      // the failure message, "" when it passed
  RegressionResult result;
  ExrImage reference;          // as read from references/<name>.exr
  ExrImage render;             // the new render, as make_reference_image writes it
  std::string working_space;   // of the R, G, B channels of both ("rec709" or "acescg")
  DisplayOptions display;      // the scene's PNG output transform
  ImageComparison comparison;  // new render against reference (relMSE, mean Delta E00, per-pixel Delta E00)
  SceneTiming timing;
  std::optional<SceneTiming> reference_timing;  // from the reference's ochre:render_seconds, when recorded

  bool passed() const { return result.passed(); }
};

// The reference EXR attribute holding the seconds its render took (written by ochre-regress --update).
inline constexpr const char* kRenderSecondsAttribute = "ochre:render_seconds";

// The R, G, B channels of an image written by make_reference_image, in working_space.
RgbImage report_rgb(const ExrImage& image, const std::string& working_space);

// The comparison and timings of a scene report, from its images (call after filling the other fields).
void compare_scene_images(SceneReport& report);

// The |z| at which a pixel fails: two_sided_p_value(z) = result.alpha_pixel.
double critical_z(const RegressionResult& result);

}  // namespace ochre
