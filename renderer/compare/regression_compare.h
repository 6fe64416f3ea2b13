#pragma once
// Noise-aware comparison of a Monte Carlo render with a reference render (the statistical image test of
// Mitsuba 3's regression suite, reduced to luminance). Both renders are estimates of the same per-pixel
// expectation; under that null hypothesis the difference of the means, divided by the square root of the
// sum of their variances of the mean, is approximately standard normal (central limit theorem). A pixel
// whose two-sided p-value falls below the Sidak-corrected level fails the whole image. docs/tools.md
// (ochre-regress) explains the choices: luminance only, the variance floor, what the test can miss.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/film/film.h"
#include "renderer/image/exr_writer.h"

namespace ochre {

// Per-pixel luminance estimate of one render: mean Y and its variance of the mean (sample variance / n).
struct LuminanceEstimate {
  int width = 0;
  int height = 0;
  double samples_per_pixel = 0;  // n of every pixel (renders use the same spp everywhere)
  std::vector<double> mean_y;
  std::vector<double> variance_of_mean;  // Var[Y] / n
};

struct RegressionResult {
  int width = 0;
  int height = 0;
  double alpha = 0.0;        // image-level significance
  double alpha_pixel = 0.0;  // Sidak-corrected per-pixel level
  double worst_p = 1.0;      // smallest per-pixel p-value
  int worst_x = 0, worst_y = 0;
  size_t failing_pixels = 0;     // pixels with p < alpha_pixel
  std::vector<double> p_values;  // per pixel, row 0 = top
  std::vector<double> z_scores;  // (Y_test - Y_ref) / sigma
  bool passed() const { return failing_pixels == 0; }
};

// The default image-level significance: a correct renderer fails a scene with probability 1 %.
constexpr double kRegressionAlpha = 0.01;

// Sidak correction: the per-pixel level at which `pixels` independent tests together reject a true null
// hypothesis with probability alpha: 1 - (1 - alpha)^(1 / pixels). Computed with log1p/expm1 so it stays
// accurate for millions of pixels.
double sidak_pixel_level(double alpha, size_t pixels);

// Two-sided p-value of a standard normal z-score: P(|Z| >= |z|) = erfc(|z| / sqrt 2).
double two_sided_p_value(double z);

// The luminance (CIE Y) estimate of a film: mean Y and variance_y / sample_count per pixel.
LuminanceEstimate luminance_from_film(const Film& film);

// Per-pixel z-test of test against reference at image-level significance alpha. Sizes must agree
// (throws std::invalid_argument otherwise).
RegressionResult compare_luminance(const LuminanceEstimate& test, const LuminanceEstimate& reference,
                                   double alpha = kRegressionAlpha);

// Reference EXR channels: R, G, B (working-space mean of `rgb`, 3 floats per pixel), "Y" (mean
// luminance), "variance.Y" (variance of the mean of Y); string attribute "ochre:regress_spp". A film with
// Stokes or spectral layers adds them as `ochre render` writes them (stokes.S0.X ..., DoLP, AoLP,
// S0.<nm> ...; renderer/output/stokes_output.h, render_output.h).
ExrImage make_reference_image(const Film& film, const std::vector<float>& rgb, uint32_t spp);

// Reads the luminance estimate back from a reference EXR; throws InputError naming the file and the
// missing channel or attribute.
LuminanceEstimate luminance_from_reference(const ExrImage& image, const std::filesystem::path& file);

// The p-value image of a comparison: channels "p.Y" (p-value) and "z.Y" (z-score).
ExrImage p_value_image(const RegressionResult& result);

// A heat map of -log10(p) with full dark red at 2 x -log10(alpha_pixel): pixels past the failure level
// are red, agreeing pixels white. PNG, written atomically.
void write_p_value_heatmap(const std::filesystem::path& path, const RegressionResult& result);
// The same into output.temp_path(), without committing (renderer/util/output_transaction.h).
void write_p_value_heatmap(AtomicOutput& output, const RegressionResult& result);

}  // namespace ochre
