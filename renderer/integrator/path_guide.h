#pragma once
// Path guiding (docs/architecture.md#path-guiding): where the light arriving at a point comes from, learned
// before the render from training paths, in a uniform grid of cells over the region the paths reach, each a
// histogram of directions over the sphere (equal solid-angle bins). A scattering samples a direction from
// its cell's histogram times the cosine to the surface's normal with probability kGuideShare, and from the
// BSDF otherwise, weighted by the mixture's density (one-sample MIS, which also weighs the light samples),
// so the image stays unbiased whatever the histogram holds: the guide moves only where samples go. After
// Mueller, Gross and Novak 2017, "Practical Path Guiding for Efficient Light-Transport Simulation" (their
// directional quadtrees and spatial binary tree become fixed bins and a uniform grid here, their doubling
// iterations one training pass, and the product with the cosine is taken per shading point).
//
// Determinism: the histograms sum integers (fixed point), so a guide is the same bits whatever the order
// of its records, i.e. for any thread count.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "materials/core/vec3.h"

namespace ochre {

// One training observation: at `p`, light of radiance `radiance` (averaged over the path's wavelengths)
// arrived along the unit world direction `dir`, which was sampled with solid-angle density `pdf`.
struct GuideRecord {
  Vec3 p;
  Vec3 dir;
  float radiance;
  float pdf;
};

class PathGuide {
 public:
  static constexpr int kZBins = 8;     // world z = cos theta, uniform: equal solid angles
  static constexpr int kPhiBins = 16;  // azimuth
  static constexpr int kBins = kZBins * kPhiBins;
  // Probability of sampling the guide rather than the BSDF where a vertex has a usable cell.
  static constexpr float kGuideShare = 0.5f;

  struct Cell {
    alignas(64) std::array<float, kBins> pmf{};  // the bins' probabilities, summing to 1
    bool usable = false;                         // learned from enough records
  };

  // A cell's histogram times the cosine to a normal at each bin's centre (zero below the surface): the
  // density a scattering samples, not normalised (`total` is the sum).
  struct Product {
    std::array<float, kBins> weight{};
    float total = 0;
  };

  // The guide of lists of training records (in any order and split: the same bits).
  static PathGuide build(const std::vector<std::vector<GuideRecord>>& records);

  // The usable cell of point p, or null (too little learned there, or outside the grid).
  const Cell* cell(const Vec3& p) const { return usable_cell(prefetch(p)); }
  // Starts loading p's cell into the cache and returns its index (-1 outside the grid), which usable_cell
  // takes: arrive() calls it before the material's evaluation, and finds the cell after it.
  ptrdiff_t prefetch(const Vec3& p) const;
  const Cell* usable_cell(ptrdiff_t index) const {
    return index >= 0 && cells_[size_t(index)].usable ? &cells_[size_t(index)] : nullptr;
  }

  // The product of `cell` with the cosine to the unit normal n; false where no bin with light faces n.
  static bool product(const Cell& cell, const Vec3& n, Product* out);
  // A direction drawn from the product (u_bin picks the bin, u the place in it) and its solid-angle density.
  static Vec3 sample(const Product& product, float u_bin, const Vec2& u, float* pdf);
  static float pdf(const Product& product, const Vec3& dir);

  static int bin_of(const Vec3& dir);
  size_t usable_cells() const;
  size_t cell_count() const { return cells_.size(); }

 private:
  // Index of the cell of p, or -1 outside the grid (or p not finite).
  ptrdiff_t cell_index(const Vec3& p) const;

  Vec3 lo_{}, cell_size_{1, 1, 1};
  std::array<int, 3> dims_{0, 0, 0};
  std::vector<Cell> cells_;
};

}  // namespace ochre
