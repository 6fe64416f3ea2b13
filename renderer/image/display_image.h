#pragma once
// Display images (8-bit sRGB PNG, or JPEG) from the renderer's linear working-space RGB, through an
// OpenColorIO display/view transform or, with ocio_config = "none", the plain sRGB transfer function.
// Files are written through AtomicOutput; PNG/JPEG through renderer/image/image_library.h (OpenImageIO).

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/image/ocio_display.h"
#include "spectra/color_space.h"

namespace ochre {

class AtomicOutput;

struct DisplayOptions {
  // "" = $OCIO, then the built-in config; "builtin"; "none" = no OCIO (clamp + sRGB transfer); or a path.
  std::string ocio_config;
  // "" = the config's default display / that display's default view.
  std::string display, view;
  // The space of the pixels, as parse_color_space() reads it: "rec709" or "acescg".
  std::string working_space = "rec709";
  // Scales the linear pixels by 2^exposure_stops before the display transform.
  float exposure_stops = 0.0f;
  // White balance before the display transform: a Bradford adaptation that maps this XYZ (an
  // illuminant's white) to D65, the white of both working spaces' display. None = no white balance.
  std::optional<std::array<double, 3>> white_balance_xyz;
};

// What a conversion used, for the caller to log.
struct DisplayTransformReport {
  // "OCIO config 'X': display 'sRGB', view 'Standard' (input colour space '...')" or
  // "built-in sRGB transfer (no OCIO)".
  std::string description;
  std::vector<std::string> warnings;
};

// Round to nearest of v * 255 after clamping to [0, 1]; NaN gives 0.
std::uint8_t quantize_unorm8(float v);
// Converts linear RGB triples in place between working spaces (through XYZ with the matrices of
// spectra/color_space.h: Bradford adaptation between the ACES white and D65).
void convert_working_space(std::vector<float>& rgb, ColorSpace from, ColorSpace to);

// Linear working-space RGB (3 floats per pixel, row 0 = top) to 8-bit display RGB. Throws ImageError
// for a bad size or option, or a config problem (naming the config).
std::vector<std::uint8_t> to_display_rgb8(int width, int height, const std::vector<float>& rgb,
                                          const DisplayOptions& options,
                                          DisplayTransformReport* report = nullptr);
// The same before quantization: display-encoded values, to_display_rgb8 = quantize_unorm8 of each (for a
// page that bakes the transform into a lattice and interpolates before it quantizes).
std::vector<float> to_display_values(int width, int height, const std::vector<float>& rgb,
                                     const DisplayOptions& options, DisplayTransformReport* report = nullptr);

// Writes an 8-bit RGB PNG (whatever the extension). Throws ImageError naming the file.
DisplayTransformReport write_display_png(const std::filesystem::path& path, int width, int height,
                                         const std::vector<float>& rgb, const DisplayOptions& options);
// The same into output.temp_path(), without committing (renderer/util/output_transaction.h).
DisplayTransformReport write_display_png(AtomicOutput& output, int width, int height,
                                         const std::vector<float>& rgb, const DisplayOptions& options);

// The display image format a path's extension names (case-insensitive): "png" for .png, "jpeg" for .jpg and
// .jpeg; nullptr for any other.
const char* display_image_format(const std::filesystem::path& path);

// Writes a PNG or a JPEG (quality 95) chosen by the extension (.png, .jpg, .jpeg); throws ImageError
// for any other extension.
DisplayTransformReport write_display_image(const std::filesystem::path& path, int width, int height,
                                           const std::vector<float>& rgb, const DisplayOptions& options);

// Writes 8-bit RGB pixels (already display-encoded) atomically; format is an OIIO format name ("png").
void write_rgb8(const std::filesystem::path& path, const char* format, int width, int height,
                const std::vector<std::uint8_t>& pixels, const std::string& description);
// The same into output.temp_path(), without committing.
void write_rgb8(AtomicOutput& output, const char* format, int width, int height,
                const std::vector<std::uint8_t>& pixels, const std::string& description);

// Reads an 8-bit image (PNG, JPEG, ... through OIIO) as RGB triples, row 0 = top; for tests and tools.
// Throws ImageError naming the file.
std::vector<std::uint8_t> read_png_rgb8(const std::filesystem::path& path, int& width, int& height);

}  // namespace ochre
