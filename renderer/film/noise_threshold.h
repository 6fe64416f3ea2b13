#pragma once
// Noise-threshold (adaptive) sampling (docs/cli.md, "Noise threshold"): each pixel takes samples until
// the relative standard error of its mean luminance Y is at most the threshold, or until the render's
// samples per pixel are done. A pixel decides only from its own samples, and only when it holds 16, 32,
// 64, ... of them: the decision does not depend on the thread count, the tile order, a region split or
// how the samples were grouped into passes, so the image is bit-identical for all of them. The pixel's
// image value is the mean of the samples it took (the film divides by each pixel's own count).

#include <cstdint>

#include "renderer/film/film.h"

namespace ochre {

// The first sample count at which a pixel may stop: fewer samples estimate the variance too poorly (a
// pixel whose first samples all missed a small light would stop black).
inline constexpr uint32_t kFirstNoiseDecision = 16;

// Whether a pixel holding `count` samples may stop there: 16, 32, 64, ... (powers of two from
// kFirstNoiseDecision).
bool is_noise_decision_point(uint64_t count);

// Whether the samples of film pixel (x, y) estimate its mean Y to a relative standard error of at most
// `threshold`: sqrt(variance / n) <= threshold * |mean| (a pixel of zero variance, black included, has
// converged).
bool pixel_converged(const Film& film, int x, int y, double threshold);

// Whether film pixel (x, y), which holds samples [0, count) for some count, takes sample `next`: it has all
// samples before it (it did not stop at an earlier decision point), and `next` is not a decision point at
// which it has converged.
bool pixel_takes_sample(const Film& film, int x, int y, uint32_t next, double threshold);

// Whether `count` samples is what a pixel of a noise-threshold render of samples [0, end) may hold: `end`,
// or a decision point below it (checks of partial-sum files).
bool valid_noise_threshold_count(uint64_t count, uint64_t end);

}  // namespace ochre
