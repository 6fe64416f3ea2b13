#pragma once
// OpenEXR output of linear images: any number of named float channels (R, G, B first, then layers such
// as "albedo.R" or the spectral "S0.550,000000nm" of Fichet et al. 2021), string metadata and the
// chromaticities of the working space. Files are written through AtomicOutput (temporary name, then
// rename). OpenEXR headers stay in the .cpp file.

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ochre {

class AtomicOutput;

// CIE xy chromaticities of an RGB space's primaries and white point (the EXR "chromaticities" attribute).
struct Chromaticities {
  std::array<float, 2> red, green, blue, white;
};

// ITU-R BT.709 primaries, D65 white: the default working space.
Chromaticities rec709_chromaticities();
// ACES AP1 primaries (SMPTE ST 2065-1 / Academy S-2014-004), ACES white (0.32168, 0.33767).
Chromaticities acescg_chromaticities();

struct ExrImage {
  int width = 0;
  int height = 0;
  // One value per pixel each, row 0 = top. EXR files store channels sorted by name, so an image read
  // back lists them in that order, whatever the order they were written in.
  std::vector<std::pair<std::string, std::vector<float>>> channels;
  std::map<std::string, std::string> string_attributes;
  std::optional<Chromaticities> chromaticities;

  // The channel called name, or nullptr.
  const std::vector<float>* find_channel(std::string_view name) const;
};

enum class ExrCompression { none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab };

// Parses "none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"; throws
// ImageError naming the value and the accepted ones.
ExrCompression parse_exr_compression(std::string_view name);

// Writes image to path (float channels, or half when half is true). Throws ImageError naming the file
// when the image is malformed (channel size, empty or duplicate names, an attribute name that the EXR
// header reserves) or the file cannot be written; an existing file is replaced only on success.
void write_exr(const std::filesystem::path& path, const ExrImage& image,
               ExrCompression compression = ExrCompression::zip, bool half = false);
// The same into output.temp_path(), without committing (several outputs: renderer/util/output_transaction.h).
void write_exr(AtomicOutput& output, const ExrImage& image, ExrCompression compression = ExrCompression::zip,
               bool half = false);

}  // namespace ochre
