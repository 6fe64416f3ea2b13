#pragma once
// The pixel values an HTML report embeds for its readout (tools/regress/scene_data.h): a grid of blocks of
// step x step pixels (step 1 = every pixel, the usual case) so that a large image stays a reasonable
// download, and the base64 text of float arrays that a page decodes into a Float32Array.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/util/base64.h"  // base64_floats, which the pages decode

namespace ochre {

struct PixelGrid {
  int width = 0, height = 0;  // the image
  int step = 1;               // pixels per block side
  int columns = 0, rows = 0;  // blocks (the last row and column may be narrower)
  size_t cells() const { return static_cast<size_t>(columns) * rows; }
};

// The grid of blocks of step x step pixels.
PixelGrid make_pixel_grid(int width, int height, int step);
// The smallest step whose grid holds at most max_values values of values_per_cell each.
PixelGrid choose_pixel_grid(int width, int height, size_t values_per_cell, size_t max_values);

// How the values of a block combine into one.
enum class BlockReduce {
  kMean,     // linear quantities (radiance, Stokes, Delta E)
  kExtreme,  // the value of largest magnitude, sign kept, NaN first (z-scores)
  kMax,      // (-log10 p)
  kSum,      // counts (failing pixels)
};

// values: `components` floats per pixel, row 0 = top; returns `components` floats per block.
std::vector<float> reduce_to_grid(const std::vector<float>& values, int components, const PixelGrid& grid,
                                  BlockReduce reduce);

}  // namespace ochre
