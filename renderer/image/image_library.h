#pragma once
// ImageLibrary: the image-file reading and writing and the texture tile cache that ochre takes from
// OpenImageIO, behind an interface whose implementation lives in a module (libochre_oiio.so) loaded on
// first use.
//
// Why: Debian's libOpenImageIO depends on ~260 shared libraries (OpenCV, GDAL, ffmpeg, libheif, ...),
// and loading them costs 0.2-0.5 s per process. Most runs of the tools need none of it: bad input, scenes
// without textures or environment maps, EXR-only output (OpenEXR directly). Linking OpenImageIO into the
// module only, and the module into nothing, lets those runs start in a few milliseconds
// (docs/performance.md, "Process start-up").
//
// The interface is deliberately low level (headers, pixels, one texture cache): policy (file checks,
// memory limits, error wording, colour decoding, atomic output) stays in the renderer, so the module
// holds no state of its own besides OpenImageIO's. Methods throw std::runtime_error with OpenImageIO's
// message (callers add the file name and context).
//
// Finding the module (image_library()): $OCHRE_IMAGE_MODULE if set (a file path), else, from the
// directory of the executable or Python extension, the installed library directory relative to the
// installed bin/ (../lib/ochre/ usually), ../lib/ochre/ (build tree: bin/), ../../lib/ochre/ (build tree:
// python/ochre/), ../../../ochre/ (installed Python package, PREFIX/lib/python3/dist-packages/ochre/), then
// the absolute installed library directory (PREFIX/lib/ochre/ of the configured prefix).

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ochre {

// What a file says of one MIP level of its first subimage.
struct ImageLevelSize {
  int width = 0, height = 0, channels = 0;
};

// The header of an image file's first subimage.
struct ImageHeader {
  int width = 0, height = 0, channels = 0;
  // The pixel format stored in the file: "uint8", "uint16", "half", "float", "double", ...
  std::string pixel_type;
  bool floating_point = false;  // half, float or double pixels (HDR, EXR), else integer
  bool tiled = false;
  int alpha_channel = -1;  // -1 when none
  std::vector<std::string> channel_names;
  std::string colorspace;              // the file's oiio:ColorSpace attribute, empty when none
  std::vector<ImageLevelSize> levels;  // MIP levels, levels[0] the full image

  bool mipmapped() const { return levels.size() > 1; }
};

using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

// The layout of a MIP-mapped texture file written by ImageLibrary::make_texture.
struct TextureFileLayout {
  bool half = true;  // half pixels, else float
  int tile_size = 64;
  ImageAttributes attributes;  // e.g. compression, wrapmodes, colorspace, provenance
};

// A texture tile cache (OpenImageIO's TextureSystem). open() must not run concurrently with lookup();
// lookup() may be called from any number of threads.
class TextureCache {
 public:
  using Handle = void*;
  virtual ~TextureCache() = default;
  // Opens the texture file; channels receives its channel count. Throws on a file it cannot read.
  virtual Handle open(const std::string& file, int& channels) = 0;
  // Filtered lookup with periodic wrap, bilinear interpolation within a MIP level and the isotropic
  // filter width `width` (s, t units; t runs down the image) of channels [first, first + count).
  // false when the read failed (the message is discarded).
  virtual bool lookup(Handle texture, int first_channel, int count, float s, float t, float width,
                      float* out) const = 0;
  virtual std::int64_t memory_used() const = 0;  // bytes held by the tile cache
  virtual std::int64_t bytes_read() const = 0;   // bytes read from files so far
};

class ImageLibrary {
 public:
  virtual ~ImageLibrary() = default;

  virtual ImageHeader read_header(const std::string& file) const = 0;
  // MIP level `level` of the first subimage, channels [0, size.channels), as float (integer formats
  // scaled to [0, 1]); size is what read_header() said of that level, and a file whose level no longer
  // has that width and height (replaced in between) throws, so the result always has
  // width x height x channels values. unassociated_alpha keeps alpha unpremultiplied, as PNG stores it.
  virtual std::vector<float> read_float(const std::string& file, int level, const ImageLevelSize& size,
                                        bool unassociated_alpha = false) const = 0;
  // The first subimage, channels [0, size.channels), as 8-bit codes (the same size check).
  virtual std::vector<std::uint8_t> read_uint8(const std::string& file, const ImageLevelSize& size) const = 0;
  // Writes 8-bit pixels (row 0 on top) as `format` ("png", "jpeg", ...) with the given attributes.
  virtual void write_uint8(const std::string& format, const std::string& file, int width, int height,
                           int channels, const std::uint8_t* pixels,
                           const ImageAttributes& attributes) const = 0;
  // Writes the float pixels (width x height x channel_names.size()) as a tiled, MIP-mapped OpenEXR
  // texture (OpenImageIO's make_texture).
  virtual void make_texture(const std::vector<float>& pixels, int width, int height,
                            const std::vector<std::string>& channel_names, int alpha_channel,
                            const TextureFileLayout& layout, const std::string& file) const = 0;
  virtual std::unique_ptr<TextureCache> create_texture_cache(float max_memory_mb) const = 0;
};

// The library, loaded on first call (thread-safe). Throws ImageError (renderer/util/image_error.h, a
// std::runtime_error) naming every place looked at when the module cannot be found or loaded.
const ImageLibrary& image_library();

// Whether the module has been loaded in this process (for tests of the start-up path).
bool image_library_loaded();

// The C entry point the module exports; version guards against a module from another build.
inline constexpr int kImageLibraryInterfaceVersion = 1;
inline constexpr const char* kImageLibraryEntryPoint = "ochre_create_image_library";
using ImageLibraryFactory = ImageLibrary* (*)(int interface_version);

}  // namespace ochre
