#pragma once
// Renders a scene text through the `ochre` CLI and reads the EXR back as luminance.

#include <string>
#include <vector>

namespace ochre::test {

struct LuminanceImage {
  int width = 0, height = 0;
  std::vector<double> y;  // CIE Y of each pixel (from linear Rec.709 RGB)
  double at(int x, int y_) const { return y[static_cast<size_t>(y_) * width + x]; }
  // Mean over the rectangle [x0, x1) x [y0, y1).
  double mean(int x0, int y0, int x1, int y1) const;
};

// Writes scene.json into a scratch dir, renders it with `extra_args`, fails the test on error.
LuminanceImage render_luminance(const std::string& scene_json, const std::string& extra_args = "");

}  // namespace ochre::test
