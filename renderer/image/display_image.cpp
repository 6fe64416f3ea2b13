#include "renderer/image/display_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "renderer/image/image_library.h"
#include "renderer/util/ascii_case.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"
#include "renderer/util/memory_budget.h"
#include "spectra/chromatic_adaptation.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

void check_size(int width, int height, const std::vector<float>& rgb, const std::string& what) {
  if (width <= 0 || height <= 0 ||
      rgb.size() != 3 * static_cast<size_t>(width) * static_cast<size_t>(height)) {
    throw ImageError(
        fmt::format("{}: {} values do not make a {}x{} RGB image", what, rgb.size(), width, height));
  }
}

// The "none" pipeline: clamp linear Rec.709 to [0, 1] (NaN to 0) and encode with the sRGB transfer
// function (IEC 61966-2-1).
void apply_srgb_transfer(std::vector<float>& rgb) {
  for (float& v : rgb) v = v > 0.0f ? srgb_encode(std::min(v, 1.0f)) : 0.0f;
}

ColorSpace parse_pixels_space(const std::string& name) {
  try {
    return parse_color_space(name);
  } catch (const std::invalid_argument& error) {
    throw ImageError(fmt::format("display image working space: {}", error.what()));
  }
}

std::vector<std::uint8_t> quantize(const std::vector<float>& encoded) {
  std::vector<std::uint8_t> pixels(encoded.size());
  for (size_t i = 0; i < encoded.size(); ++i) pixels[i] = quantize_unorm8(encoded[i]);
  return pixels;
}

const char* format_for_extension(const std::filesystem::path& path) {
  if (const char* format = display_image_format(path)) return format;
  throw ImageError(
      fmt::format("cannot write {}: unknown display image extension '{}' (expected .png, .jpg or .jpeg)",
                  path.string(), lower_extension(path)));
}

}  // namespace

const char* display_image_format(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".png") return "png";
  if (extension == ".jpg" || extension == ".jpeg") return "jpeg";
  return nullptr;
}

void write_rgb8(const std::filesystem::path& path, const char* format, int width, int height,
                const std::vector<std::uint8_t>& pixels, const std::string& description) {
  AtomicOutput output(path);
  write_rgb8(output, format, width, height, pixels, description);
  output.commit();
}

void write_rgb8(AtomicOutput& atomic, const char* format, int width, int height,
                const std::vector<std::uint8_t>& pixels, const std::string& description) {
  const std::string file = atomic.final_path().string();
  ImageAttributes attributes = {{"Software", "ochre"}, {"ImageDescription", description}};
  if (std::string_view(format) == "jpeg") attributes.emplace_back("Compression", "jpeg:95");
  try {
    image_library().write_uint8(format, atomic.temp_path().string(), width, height, 3, pixels.data(),
                                attributes);
  } catch (const std::runtime_error& e) {
    throw ImageError(fmt::format("cannot write {}: {}", file, e.what()));
  }
}

std::uint8_t quantize_unorm8(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

void convert_working_space(std::vector<float>& rgb, ColorSpace from, ColorSpace to) {
  if (from == to) return;
  const Mat3 m = xyz_to_rgb_matrix(to) * rgb_to_xyz_matrix(from);
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const Array3d converted = m * Array3d{rgb[i], rgb[i + 1], rgb[i + 2]};
    for (int c = 0; c < 3; ++c) rgb[i + c] = static_cast<float>(converted[c]);
  }
}

namespace {

// Maps the illuminant white `white_xyz` to D65 (the white of Rec.709; ACEScg pixels go through their
// D65-referred matrices, so the same holds) by a Bradford adaptation in XYZ, like a camera's white balance.
void apply_white_balance(std::vector<float>& rgb, ColorSpace space, const std::array<double, 3>& white_xyz) {
  const Array3d d65 = rgb_to_xyz_matrix(ColorSpace::LinearRec709) * Array3d{1, 1, 1};
  const Mat3 m = xyz_to_rgb_matrix(space) *
                 bradford_adaptation({white_xyz[0], white_xyz[1], white_xyz[2]}, d65) *
                 rgb_to_xyz_matrix(space);
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const Array3d balanced = m * Array3d{rgb[i], rgb[i + 1], rgb[i + 2]};
    for (int c = 0; c < 3; ++c) rgb[i + c] = static_cast<float>(balanced[c]);
  }
}

}  // namespace

std::vector<std::uint8_t> to_display_rgb8(int width, int height, const std::vector<float>& rgb,
                                          const DisplayOptions& options, DisplayTransformReport* report) {
  return quantize(to_display_values(width, height, rgb, options, report));
}

std::vector<float> to_display_values(int width, int height, const std::vector<float>& rgb,
                                     const DisplayOptions& options, DisplayTransformReport* report) {
  check_size(width, height, rgb, "display image");
  const ColorSpace pixels_space = parse_pixels_space(options.working_space);
  if (!std::isfinite(options.exposure_stops)) {
    throw ImageError(
        fmt::format("display image: exposure {} is not a finite number", options.exposure_stops));
  }
  std::vector<float> work = rgb;
  if (options.white_balance_xyz) apply_white_balance(work, pixels_space, *options.white_balance_xyz);
  if (options.exposure_stops != 0.0f) {
    const float scale = std::exp2(options.exposure_stops);
    for (float& v : work) v *= scale;
  }

  DisplayTransformReport used;
  if (options.ocio_config == "none") {
    convert_working_space(work, pixels_space, ColorSpace::LinearRec709);
    apply_srgb_transfer(work);
    used.description = "built-in sRGB transfer (no OCIO)";
  } else {
    const OcioDisplay display(options.ocio_config, options.display, options.view, pixels_space);
    convert_working_space(work, pixels_space, display.input_space());
    display.apply(work, width, height);
    used.description = display.description();
    used.warnings = display.warnings();
  }
  if (report) *report = used;
  return work;
}

DisplayTransformReport write_display_png(const std::filesystem::path& path, int width, int height,
                                         const std::vector<float>& rgb, const DisplayOptions& options) {
  AtomicOutput output(path);
  const DisplayTransformReport report = write_display_png(output, width, height, rgb, options);
  output.commit();
  return report;
}

DisplayTransformReport write_display_png(AtomicOutput& output, int width, int height,
                                         const std::vector<float>& rgb, const DisplayOptions& options) {
  check_size(width, height, rgb, fmt::format("cannot write {}", output.final_path().string()));
  DisplayTransformReport report;
  const std::vector<std::uint8_t> pixels = to_display_rgb8(width, height, rgb, options, &report);
  write_rgb8(output, "png", width, height, pixels, report.description);
  return report;
}

DisplayTransformReport write_display_image(const std::filesystem::path& path, int width, int height,
                                           const std::vector<float>& rgb, const DisplayOptions& options) {
  const char* format = format_for_extension(path);
  check_size(width, height, rgb, fmt::format("cannot write {}", path.string()));
  DisplayTransformReport report;
  const std::vector<std::uint8_t> pixels = to_display_rgb8(width, height, rgb, options, &report);
  write_rgb8(path, format, width, height, pixels, report.description);
  return report;
}

std::vector<std::uint8_t> read_png_rgb8(const std::filesystem::path& path, int& width, int& height) {
  const std::string file = path.string();
  check_regular_input(path, kImageFileInput);  // a FIFO or a device is refused before OIIO opens it
  const auto unreadable = [&](const std::string& why) {
    return ImageError(fmt::format("cannot read {}: {}", file, why));
  };
  ImageHeader header;
  try {
    header = image_library().read_header(file);
  } catch (const std::runtime_error& e) {
    throw unreadable(e.what());
  }
  if (header.channels < 3) throw unreadable(fmt::format("{} channel(s), expected RGB", header.channels));
  width = header.width;
  height = header.height;
  check_memory_estimate(3.0 * width * height, fmt::format("reading {} ({}x{})", file, width, height));
  try {
    return image_library().read_uint8(file, {width, height, 3});
  } catch (const std::runtime_error& e) {
    throw unreadable(e.what());
  }
}

}  // namespace ochre
