#pragma once
// Image comparison for regression testing (ochre-diff, docs/tools.md): scene-referred error metrics on
// the R, G, B channels of two linear images, the mean CIEDE2000 of their display-referred colours, and
// an error heat-map. The second image of every comparison is the reference.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/image/display_image.h"
#include "renderer/image/exr_writer.h"

namespace ochre {

// Linear RGB, 3 floats per pixel, row 0 = top, in the working space named as DisplayOptions reads it.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
  std::string working_space = "rec709";
};

// The R, G, B channels of an EXR; the working space is "acescg" when the chromaticities attribute is
// that of ACES AP1, else "rec709". Throws InputError naming the file when a channel is missing.
RgbImage rgb_from_exr(const ExrImage& exr, const std::filesystem::path& file);

// Throws InputError naming both files when sizes or working spaces differ, and naming the reference and
// the pixel when a reference value is NaN or infinite.
void check_comparable(const RgbImage& test, const RgbImage& reference, const std::string& test_name,
                      const std::string& reference_name);

// Added to reference^2 in the relative MSE so that black reference pixels do not divide by zero.
inline constexpr double kRelMseEpsilon = 1e-2;

struct ImageMetrics {
  double rmse = 0.0;       // sqrt(mean over pixels and channels of (a - b)^2)
  double relmse = 0.0;     // mean over pixels and channels of (a - b)^2 / (b^2 + kRelMseEpsilon)
  double max_error = 0.0;  // max over pixels and channels of |a - b|
  int max_error_x = 0, max_error_y = 0, max_error_channel = 0;  // where (first such value, row-major)
  double mean_de00 = 0.0;  // mean over pixels of CIEDE2000 of the display-referred colours
  double max_de00 = 0.0;
};

// Per-pixel error maps (row-major, one value per pixel).
struct ErrorMaps {
  std::vector<float> abs_luminance;  // luminance of (|dR|, |dG|, |dB|) in the working space
  std::vector<float> de00;           // CIEDE2000 of the display-referred colours
};

struct ImageComparison {
  ImageMetrics metrics;
  ErrorMaps maps;
};

// Compares test against reference (same size and working space: call check_comparable first). Both
// are shown through the same display transform (to_display_rgb8 with display), sRGB-decoded to linear,
// converted to XYZ (D65) and CIELAB, then compared with CIEDE2000. NaN or infinite values make the
// metrics they reach NaN or infinite. Throws ImageError on a display configuration problem.
ImageComparison compare_images(const RgbImage& test, const RgbImage& reference,
                               const DisplayOptions& display);

// The display-referred CIEDE2000 of every pixel pair, from 8-bit sRGB-encoded triples.
std::vector<float> display_de00(const std::vector<std::uint8_t>& test,
                                const std::vector<std::uint8_t>& reference);

struct MetricThresholds {
  std::optional<double> rmse, relmse, max_error, max_de;
};

// One line per threshold exceeded, e.g. "rmse 0.0123 > 0.01"; a NaN metric exceeds any threshold.
std::vector<std::string> exceeded_thresholds(const ImageMetrics& metrics, const MetricThresholds& thresholds);

// The heat-map colour ramp, t in [0, 1] (clamped; NaN -> 1): white (no error) through pale yellow and
// orange to dark red (largest error), CIELAB lightness decreasing monotonically. 8-bit sRGB.
std::array<std::uint8_t, 3> heatmap_colour(double t);

// Writes an 8-bit sRGB PNG of values / scale mapped through heatmap_colour (scale <= 0: all zero
// error), atomically. Throws ImageError naming the file.
void write_heatmap_png(const std::filesystem::path& path, int width, int height,
                       const std::vector<float>& values, double scale);
// The same into output.temp_path(), without committing (renderer/util/output_transaction.h).
void write_heatmap_png(AtomicOutput& output, int width, int height, const std::vector<float>& values,
                       double scale);

}  // namespace ochre
