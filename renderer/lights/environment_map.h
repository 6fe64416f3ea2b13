#pragma once
// EnvironmentMap: an HDR latitude-longitude (equirectangular) image of the radiance arriving from
// infinity, in linear Rec.709 RGB, with a piecewise-constant importance-sampling distribution.
//
// Convention (+y up). For a unit direction d = (x, y, z) in the map's own frame:
//   phi   = atan2(x, -z)  in (-pi, pi]      (0 along -z, +pi/2 along +x)
//   theta = acos(y)       in [0, pi]        (0 along +y)
//   u = 1/2 + phi / (2 pi),  v = theta / pi,  column = floor(u * width), row = floor(v * height)
// so the centre of the image looks along -z, +x is a quarter of the width to the right of the centre,
// the top row is +y and the bottom row -y:
//
//   u = 0        0.25        0.5        0.75        1
//   +-----------+-----------+-----------+-----------+   v = 0    (+y, zenith)
//   |           |           |           |           |
//   +z         -x          -z          +x          +z   v = 0.5  (horizon)
//   |           |           |           |           |
//   +-----------+-----------+-----------+-----------+   v = 1    (-y, nadir)
//
// (Seen from inside the sphere looking along -z with +y up, +x is on the right, as in the image.)
//
// Texels are looked up nearest-neighbour, so radiance is constant over each texel's patch of the
// sphere, and the sampling density is piecewise constant per texel as well:
//   weight(texel) = (luminance + floor) * sin(theta at the row's centre),  floor = 1e-3 x mean luminance,
//   pdf(direction) = pdf_uv / (2 pi^2 sin theta)                         (pbrt-v4, section 12.5.2).
// The floor keeps every direction samplable (pdf > 0), so sample() alone is an unbiased estimator too.
//
// Texel keys: the distribution stores its densities in blocks of 4 x 4 texels (distribution_2d.h); a texel's
// key is its position in that block-major order. Per-texel data a sample or an escaping ray reads next to the
// density (EnvironmentLight's spectra) is stored by key, so that neighbouring texels share cache lines in
// both directions. Keys lie in [0, texel_key_count()), which includes padding texels past the image's edges.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "materials/core/vec3.h"
#include "renderer/sampling/distribution_2d.h"
#include "spectra/color_types.h"

namespace ochre {

// The (u, v) of a direction (need not be normalised; must not be zero), and the unit direction of a
// (u, v) point, in the map's frame (see the drawing above).
Vec2 direction_to_equirect_uv(const Vec3& direction);
Vec3 equirect_uv_to_direction(const Vec2& uv);

class EnvironmentMap {
 public:
  struct Sample {
    Vec3 direction;    // unit, map frame
    size_t index = 0;  // texel index (row * width + column): texel(index) is its value
    size_t key = 0;    // the same texel's key
    float pdf = 0.0f;  // solid-angle density (0: the sample must be discarded)
  };

  // rgb: width * height texels, row 0 = top. Negative or non-finite components throw
  // std::invalid_argument naming the texel (a light never emits negative radiance; an out-of-gamut map
  // must be clipped or converted by the user, not silently).
  EnvironmentMap(int width, int height, std::vector<RGB> rgb);

  // Reads a linear HDR image (.hdr, .exr, ... anything OpenImageIO reads as floating point) with 1
  // (grey), 3 or more channels (the first three are R, G, B). Throws std::runtime_error with the
  // reason (missing, unreadable, 8-bit, NaN or negative texel, ...); the caller adds the file and the field.
  static EnvironmentMap load(const std::filesystem::path& path);

  int width() const { return width_; }
  int height() const { return height_; }
  const RGB& texel(int column, int row) const { return rgb_[static_cast<size_t>(row) * width_ + column]; }
  // Nearest texel along a direction of the map frame, and its index (row * width + column).
  const RGB& lookup(const Vec3& direction) const { return rgb_[texel_index(direction)]; }
  size_t texel_index(const Vec3& direction) const;
  size_t texel_count() const { return rgb_.size(); }
  const RGB& texel(size_t index) const { return rgb_[index]; }

  // Texel keys (see above).
  size_t texel_key(int column, int row) const { return distribution_.cell_key(column, row); }
  size_t texel_key(const Vec3& direction) const;
  size_t texel_key_count() const { return distribution_.key_count(); }

  Sample sample(const Vec2& u) const { return sample_in_block(distribution_.choose_block(u)); }
  // The second stage of sample(u) (Distribution2D::choose_block() is the first), for a caller that
  // prefetches its per-texel data for the chosen block in between.
  Sample sample_in_block(const Distribution2D::BlockChoice& choice) const;
  // The key of the texel along a direction of the map frame and the solid-angle density of sample() there
  // (one (u, v) computation for both, as a ray escaping the scene needs).
  size_t texel_key_and_pdf(const Vec3& direction, float* pdf) const;
  // Solid-angle density of sample() producing `direction` (map frame, need not be normalised).
  float pdf(const Vec3& direction) const;

  // Mean over the sphere (solid-angle weighted) of the texel luminance (Rec.709 Y).
  double mean_luminance() const { return mean_luminance_; }
  const Distribution2D& distribution() const { return distribution_; }

 private:
  int width_;
  int height_;
  std::vector<RGB> rgb_;
  Distribution2D distribution_;
  double mean_luminance_ = 0.0;
};

}  // namespace ochre
