#include "cli/point_light_and_sky.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli/render_probe.h"

namespace ochre::test {

PointLightAndSky render_point_light_and_sky(const std::string& integrator_fields) {
  const double rho = 0.5, I = 10.0, h = 1.0, Le = 0.2, view = 4.0;
  const int res = 16;
  const LuminanceImage img = render_luminance(fmt::format(R"({{
      "camera": {{"type": "orthographic", "size": {}, "eye": [0, 0, 5], "target": [0, 0, 0]}},
      "film": {{"resolution": [{}, {}]}},
      "integrator": {{{}}},
      "materials": {{"m": {{"type": "lambert", "color": {}}}}},
      "lights": [{{"type": "point", "position": [0, 0, {}], "intensity": {}}},
                 {{"type": "environment", "radiance": {}}}],
      "shapes": [{{"type": "plane", "size": [100, 100], "material": "m"}}]
    }})",
                                                          view, res, res, integrator_fields, rho, h, I, Le));
  EXPECT_EQ(img.width, res);
  PointLightAndSky out;
  if (img.width != res) return out;
  double sum = 0.0, sum_expected = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      double expected = 0.0;  // averaged over the pixel (box filter), 8 x 8 points
      for (int sj = 0; sj < 8; ++sj)
        for (int si = 0; si < 8; ++si) {
          const double x = (i + (si + 0.5) / 8) / res * view - view / 2;
          const double y = view / 2 - (j + (sj + 0.5) / 8) / res * view;
          const double r2 = x * x + y * y + h * h;
          expected += (rho / M_PI * I * (h / std::sqrt(r2)) / r2 + rho * Le) / 64.0;
        }
      out.worst = std::max(out.worst, std::fabs(img.at(i, j) / expected - 1.0));
      sum += img.at(i, j);
      sum_expected += expected;
    }
  out.mean = sum / (res * res);
  out.expected_mean = sum_expected / (res * res);
  return out;
}

}  // namespace ochre::test
