#include "tools/regress/scene_report.h"

#include <cstdlib>

namespace ochre {

namespace {

std::optional<SceneTiming> recorded_timing(const ExrImage& reference) {
  const auto seconds = reference.string_attributes.find(kRenderSecondsAttribute);
  const auto spp = reference.string_attributes.find("ochre:regress_spp");
  if (seconds == reference.string_attributes.end() || spp == reference.string_attributes.end())
    return std::nullopt;
  SceneTiming timing;
  char* end = nullptr;
  timing.seconds = std::strtod(seconds->second.c_str(), &end);
  if (end == seconds->second.c_str() || !(timing.seconds >= 0.0)) return std::nullopt;
  timing.spp = std::strtod(spp->second.c_str(), &end);
  if (end == spp->second.c_str() || !(timing.spp > 0.0)) return std::nullopt;
  return timing;
}

}  // namespace

RgbImage report_rgb(const ExrImage& image, const std::string& working_space) {
  RgbImage rgb;
  rgb.width = image.width;
  rgb.height = image.height;
  rgb.working_space = working_space;
  const size_t n = static_cast<size_t>(image.width) * image.height;
  rgb.rgb.assign(3 * n, 0.0f);
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c)
    if (const std::vector<float>* channel = image.find_channel(names[c]))
      for (size_t p = 0; p < n && p < channel->size(); ++p) rgb.rgb[3 * p + c] = (*channel)[p];
  return rgb;
}

void compare_scene_images(SceneReport& report) {
  report.comparison = compare_images(report_rgb(report.render, report.working_space),
                                     report_rgb(report.reference, report.working_space), report.display);
  report.reference_timing = recorded_timing(report.reference);
}

double critical_z(const RegressionResult& result) {
  // two_sided_p_value decreases in |z|: bisection to float precision.
  double low = 0.0, high = 40.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (two_sided_p_value(mid) > result.alpha_pixel ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace ochre
