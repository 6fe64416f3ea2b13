#pragma once
// Pixel reconstruction filter, applied by filter importance sampling: each camera sample's position in
// its pixel is drawn with the density of the filter, so every sample keeps weight 1 and stays in its own
// pixel's sum (the film's exact, split-independent sums are kept; docs/architecture.md, 'Film'). The
// expected pixel value is the radiance convolved with the normalised filter, which is what a renderer
// that splats weighted samples into neighbouring pixels converges to (Mitsuba 3, pbrt-v4's filter
// sampling).
//   box       uniform over a square of half-width `radius` pixels about the pixel centre (0.5: the pixel)
//   gaussian  exp(-x^2 / (2 stddev^2)) - exp(-r^2 / (2 stddev^2)) per axis, cut at r = 4 stddev
//             (Mitsuba 3's gaussian rfilter)

#include <string>
#include <vector>

#include "materials/core/vec3.h"
#include "renderer/sampling/distribution_1d.h"

namespace ochre {

class PixelFilter {
 public:
  static PixelFilter box(float radius = 0.5f);
  static PixelFilter gaussian(float stddev);

  // The sample's position relative to the pixel's corner, from u in [0,1)^2; the pixel box of radius
  // 0.5 returns u itself.
  Vec2 sample(Vec2 u) const;
  float radius() const { return radius_; }
  // "box (radius 0.5)", "gaussian (stddev 0.5, radius 2)".
  std::string description() const;

 private:
  float sample_axis(float u) const;

  bool gaussian_ = false;
  float radius_ = 0.5f;
  float stddev_ = 0.0f;
  Distribution1D cells_;  // the gaussian's weight over equal cells of [-radius, radius]
};

}  // namespace ochre
