#include "tools/regress/report_images.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tools/regress/pixel_grid.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

void write_z_heatmap(const fs::path& path, const RegressionResult& result) {
  const double full_scale = kZFullScaleFactor * critical_z(result);
  std::vector<std::uint8_t> pixels(result.z_scores.size() * 3);
  for (size_t i = 0; i < result.z_scores.size(); ++i) {
    const auto colour = diverging_colour(result.z_scores[i] / full_scale);
    std::copy(colour.begin(), colour.end(), pixels.begin() + static_cast<std::ptrdiff_t>(3 * i));
  }
  write_rgb8(path, "png", result.width, result.height, pixels,
             fmt::format("z-scores of the luminance test, full scale +-{:.3g}", full_scale));
}

// The display image of rgb, box-filtered to at most kThumbnailSize pixels a side.
void write_thumbnail(const fs::path& path, const RgbImage& image, const DisplayOptions& display) {
  const int longest = std::max(image.width, image.height);
  const PixelGrid grid =
      make_pixel_grid(image.width, image.height, (longest + kThumbnailSize - 1) / kThumbnailSize);
  write_display_png(path, grid.columns, grid.rows, reduce_to_grid(image.rgb, 3, grid, BlockReduce::kMean),
                    display);
}

}  // namespace

std::array<std::uint8_t, 3> diverging_colour(double t) {
  // ColorBrewer RdBu (Brewer, colorbrewer2.org), readable with the common colour vision deficiencies.
  static constexpr std::array<std::array<double, 3>, 5> ramp = {{
      {33, 102, 172},   // -1: dark blue
      {146, 197, 222},  // light blue
      {247, 247, 247},  // 0: white
      {244, 165, 130},  // light red
      {178, 24, 43},    // +1: dark red
  }};
  if (std::isnan(t)) return {0, 0, 0};
  const double position = (std::clamp(t, -1.0, 1.0) + 1.0) * 0.5 * static_cast<double>(ramp.size() - 1);
  const size_t i = std::min(static_cast<size_t>(position), ramp.size() - 2);
  const double f = position - static_cast<double>(i);
  std::array<std::uint8_t, 3> colour{};
  for (int c = 0; c < 3; ++c)
    colour[c] = static_cast<std::uint8_t>(std::lround(ramp[i][c] + f * (ramp[i + 1][c] - ramp[i][c])));
  return colour;
}

SceneImageFiles write_scene_images(const SceneReport& report, const fs::path& dir,
                                   const std::string& prefix) {
  SceneImageFiles files{prefix + ".reference.png", prefix + ".new.png",       prefix + ".difference.png",
                        prefix + ".z.png",         prefix + ".reference.png", prefix + ".new.png"};
  const RgbImage reference = report_rgb(report.reference, report.working_space);
  const RgbImage render = report_rgb(report.render, report.working_space);
  write_display_png(dir / files.reference, reference.width, reference.height, reference.rgb, report.display);
  write_display_png(dir / files.render, render.width, render.height, render.rgb, report.display);
  write_heatmap_png(dir / files.difference, render.width, render.height, report.comparison.maps.de00,
                    kDe00FullScale);
  write_z_heatmap(dir / files.z, report.result);
  if (std::max(render.width, render.height) > kThumbnailSize) {
    files.reference_thumbnail = prefix + ".thumb-reference.png";
    files.render_thumbnail = prefix + ".thumb-new.png";
    write_thumbnail(dir / files.reference_thumbnail, reference, report.display);
    write_thumbnail(dir / files.render_thumbnail, render, report.display);
  }
  return files;
}

}  // namespace ochre
