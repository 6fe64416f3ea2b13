#include "renderer/compare/image_metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "renderer/image/image_library.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"
#include "spectra/ciede2000.h"
#include "spectra/color_space.h"
#include "spectra/input_error.h"

namespace ochre {

namespace {

bool same_chromaticities(const Chromaticities& a, const Chromaticities& b) {
  const auto close = [](const std::array<float, 2>& p, const std::array<float, 2>& q) {
    return std::abs(p[0] - q[0]) < 1e-4f && std::abs(p[1] - q[1]) < 1e-4f;
  };
  return close(a.red, b.red) && close(a.green, b.green) && close(a.blue, b.blue) && close(a.white, b.white);
}

// Luminance weights of the working space: the Y row of its RGB -> XYZ matrix.
std::array<double, 3> luminance_weights(const std::string& working_space) {
  const Mat3& m = rgb_to_xyz_matrix(parse_color_space(working_space));
  return {(m * Array3d{1, 0, 0})[1], (m * Array3d{0, 1, 0})[1], (m * Array3d{0, 0, 1})[1]};
}

// Records the largest |a - b| and where it is; a NaN difference wins over any number (first one kept).
void track_max_error(ImageMetrics& metrics, double error, size_t pixel, int channel, int width) {
  const bool larger = std::isnan(error) ? !std::isnan(metrics.max_error) : error > metrics.max_error;
  if (!larger) return;
  metrics.max_error = error;
  metrics.max_error_x = static_cast<int>(pixel % static_cast<size_t>(width));
  metrics.max_error_y = static_cast<int>(pixel / static_cast<size_t>(width));
  metrics.max_error_channel = channel;
}

// CIELAB of an 8-bit sRGB-encoded triple: decode (IEC 61966-2-1), XYZ (D65), Lab relative to D65.
Lab display_lab(const std::uint8_t* code) {
  static const std::array<double, 256> decoded = [] {
    std::array<double, 256> table{};
    for (int i = 0; i < 256; ++i) table[i] = srgb_decode(static_cast<float>(i) / 255.0f);
    return table;
  }();
  return xyz_to_lab(linear_srgb_to_xyz(decoded[code[0]], decoded[code[1]], decoded[code[2]]),
                    srgb_d65_white());
}

}  // namespace

RgbImage rgb_from_exr(const ExrImage& exr, const std::filesystem::path& file) {
  RgbImage image;
  image.width = exr.width;
  image.height = exr.height;
  const size_t pixels = static_cast<size_t>(exr.width) * static_cast<size_t>(exr.height);
  image.rgb.resize(3 * pixels);
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    const std::vector<float>* channel = exr.find_channel(names[c]);
    if (!channel)
      throw InputError(
          fmt::format("{}: no channel '{}' (ochre-diff compares R, G, B)", file.string(), names[c]));
    for (size_t i = 0; i < pixels; ++i) image.rgb[3 * i + c] = (*channel)[i];
  }
  if (exr.chromaticities && same_chromaticities(*exr.chromaticities, acescg_chromaticities())) {
    image.working_space = "acescg";
  }
  return image;
}

void check_comparable(const RgbImage& test, const RgbImage& reference, const std::string& test_name,
                      const std::string& reference_name) {
  if (test.width != reference.width || test.height != reference.height) {
    throw InputError(fmt::format("size mismatch: {} is {}x{}, {} is {}x{}", test_name, test.width,
                                 test.height, reference_name, reference.width, reference.height));
  }
  if (test.working_space != reference.working_space) {
    throw InputError(fmt::format("working space mismatch: {} is {}, {} is {}", test_name, test.working_space,
                                 reference_name, reference.working_space));
  }
  // A reference is the truth the metrics measure against: a NaN or infinite value in it would make every
  // metric NaN (and pass every threshold test unseen), so it is bad input. (A test image may hold them: its
  // metrics are then NaN and fail any threshold.)
  for (size_t i = 0; i < reference.rgb.size(); ++i)
    if (!std::isfinite(reference.rgb[i])) {
      const size_t pixel = i / 3;
      throw InputError(fmt::format("{}: pixel ({}, {}) channel {} is {}: a reference must be finite",
                                   reference_name, pixel % static_cast<size_t>(reference.width),
                                   pixel / static_cast<size_t>(reference.width), "RGB"[i % 3],
                                   reference.rgb[i]));
    }
}

ImageComparison compare_images(const RgbImage& test, const RgbImage& reference,
                               const DisplayOptions& display) {
  const size_t pixels = static_cast<size_t>(test.width) * static_cast<size_t>(test.height);
  if (test.rgb.size() != 3 * pixels || reference.rgb.size() != 3 * pixels) {
    throw InputError("compare_images: images of different sizes (call check_comparable first)");
  }
  const std::array<double, 3> weights = luminance_weights(test.working_space);

  ImageComparison result;
  ImageMetrics& m = result.metrics;
  result.maps.abs_luminance.resize(pixels);
  double squared_sum = 0.0, relative_sum = 0.0;
  for (size_t p = 0; p < pixels; ++p) {
    double abs_luminance = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double a = test.rgb[3 * p + c];
      const double b = reference.rgb[3 * p + c];
      const double d = a - b;
      squared_sum += d * d;
      relative_sum += d * d / (b * b + kRelMseEpsilon);
      abs_luminance += weights[c] * std::abs(d);
      track_max_error(m, std::abs(d), p, c, test.width);
    }
    result.maps.abs_luminance[p] = static_cast<float>(abs_luminance);
  }
  const double samples = 3.0 * static_cast<double>(pixels);
  m.rmse = pixels ? std::sqrt(squared_sum / samples) : 0.0;
  m.relmse = pixels ? relative_sum / samples : 0.0;

  DisplayOptions options = display;
  options.working_space = test.working_space;
  const auto test_display = to_display_rgb8(test.width, test.height, test.rgb, options);
  const auto reference_display = to_display_rgb8(reference.width, reference.height, reference.rgb, options);
  result.maps.de00 = display_de00(test_display, reference_display);
  double de_sum = 0.0;
  for (float de : result.maps.de00) {
    de_sum += de;
    m.max_de00 = std::max(m.max_de00, static_cast<double>(de));
  }
  m.mean_de00 = pixels ? de_sum / static_cast<double>(pixels) : 0.0;
  return result;
}

std::vector<float> display_de00(const std::vector<std::uint8_t>& test,
                                const std::vector<std::uint8_t>& reference) {
  const size_t pixels = std::min(test.size(), reference.size()) / 3;
  std::vector<float> de(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    de[p] = static_cast<float>(ciede2000(display_lab(&reference[3 * p]), display_lab(&test[3 * p])));
  }
  return de;
}

std::vector<std::string> exceeded_thresholds(const ImageMetrics& metrics,
                                             const MetricThresholds& thresholds) {
  std::vector<std::string> exceeded;
  const auto check = [&](const char* name, double value, const std::optional<double>& limit) {
    if (limit && !(value <= *limit))
      exceeded.push_back(fmt::format("{} {:.6g} > {:.6g}", name, value, *limit));
  };
  check("rmse", metrics.rmse, thresholds.rmse);
  check("relmse", metrics.relmse, thresholds.relmse);
  check("max-error", metrics.max_error, thresholds.max_error);
  check("mean-de00", metrics.mean_de00, thresholds.max_de);
  return exceeded;
}

std::array<std::uint8_t, 3> heatmap_colour(double t) {
  // Control points in 8-bit sRGB (our own ramp): CIELAB L* of about 100, 92, 75, 55, 34.
  static constexpr std::array<std::array<double, 3>, 5> ramp = {{
      {255, 255, 255},  // no error: white
      {254, 230, 140},  // pale yellow
      {253, 160, 60},   // orange
      {230, 60, 30},    // red
      {165, 0, 20},     // largest error: dark red
  }};
  t = std::isnan(t) ? 1.0 : std::clamp(t, 0.0, 1.0);
  const double position = t * static_cast<double>(ramp.size() - 1);
  const size_t i = std::min(static_cast<size_t>(position), ramp.size() - 2);
  const double f = position - static_cast<double>(i);
  std::array<std::uint8_t, 3> colour{};
  for (int c = 0; c < 3; ++c) {
    colour[c] = static_cast<std::uint8_t>(std::lround(ramp[i][c] + f * (ramp[i + 1][c] - ramp[i][c])));
  }
  return colour;
}

void write_heatmap_png(const std::filesystem::path& path, int width, int height,
                       const std::vector<float>& values, double scale) {
  AtomicOutput output(path);
  write_heatmap_png(output, width, height, values, scale);
  output.commit();
}

void write_heatmap_png(AtomicOutput& atomic, int width, int height, const std::vector<float>& values,
                       double scale) {
  const std::string file = atomic.final_path().string();
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  if (width <= 0 || height <= 0 || values.size() != pixels) {
    throw ImageError(fmt::format("cannot write {}: {} values do not make a {}x{} heat-map", file,
                                 values.size(), width, height));
  }
  std::vector<std::uint8_t> codes(3 * pixels);
  for (size_t p = 0; p < pixels; ++p) {
    const double t = scale > 0.0 ? values[p] / scale : 0.0;
    const auto colour = heatmap_colour(t);
    std::copy(colour.begin(), colour.end(), codes.begin() + static_cast<std::ptrdiff_t>(3 * p));
  }

  const ImageAttributes attributes = {
      {"Software", "ochre-diff"},
      {"ImageDescription", fmt::format("error heat-map, full scale {:.6g}", scale)}};
  try {
    image_library().write_uint8("png", atomic.temp_path().string(), width, height, 3, codes.data(),
                                attributes);
  } catch (const std::runtime_error& e) {
    throw ImageError(fmt::format("cannot write {}: {}", file, e.what()));
  }
}

}  // namespace ochre
