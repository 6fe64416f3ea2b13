#pragma once
// Filtered texture lookups for material graphs through OpenImageIO's TextureSystem.
//
// Colour: shading works on linear values, and OIIO 2.4's TextureSystem does not colour-convert on
// lookup. A texture whose file is sRGB-encoded (8/16-bit JPEG, PNG, TIFF, ...) is therefore decoded to
// linear once, when it is added, BEFORE any filtering: averaging encoded values and decoding the average
// would darken every filtered region. The decoded image is written as a tiled, MIP-mapped half/float
// OpenEXR file into a cache directory and the TextureSystem reads that file.
//
// Texture coordinates: mesh uv follow the OpenGL/glTF convention (v = 0 at the BOTTOM row of the
// image); OIIO's t runs down the image (t = 0 at the top row), so lookups use s = u, t = 1 - v.
//
// Memory: a texture whose MIP levels fit in the resident budget (as float; 512 MiB for all textures
// together by default) is read into memory once (renderer/texture/mip_pyramid.h) and looked up there, several
// times faster than through the TextureSystem; larger ones (photogrammetry textures of 8k and more) stay
// paged through OIIO's tile cache. The results agree to float rounding at level 0 and to the MIP
// filtering's blend between levels otherwise.
//
// Threads: lookup() may be called concurrently from any number of threads (it uses per-thread OIIO
// state and allocates nothing per call). add_texture() must not run concurrently with lookup(): add all
// textures while loading the scene, then render.
//
// OpenImageIO is reached through renderer/image/image_library.h (a module loaded with the first texture).

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include "materials/nodes/texture_provider.h"

namespace ochre {

// Where converted textures are cached: $OCHRE_CACHE_DIR, else $XDG_CACHE_HOME/ochre/textures, else
// $HOME/.cache/ochre/textures, else <system temp dir>/ochre-textures. Empty variables count as unset.
std::filesystem::path default_texture_cache_dir();

class OiioTextureProvider final : public TextureProvider {
 public:
  // cache_dir empty = default_texture_cache_dir(). When that directory cannot be created or written,
  // <system temp dir>/ochre-textures is used instead (cache_dir() tells which, stats() says why).
  // resident_budget_bytes: how many bytes of MIP levels (float) may be held in memory (0 = none: every
  // lookup goes through the TextureSystem).
  static constexpr std::size_t kDefaultResidentBudget = std::size_t{512} << 20;
  explicit OiioTextureProvider(std::filesystem::path cache_dir = {},
                               std::size_t resident_budget_bytes = kDefaultResidentBudget);
  ~OiioTextureProvider() override;
  OiioTextureProvider(const OiioTextureProvider&) = delete;
  OiioTextureProvider& operator=(const OiioTextureProvider&) = delete;

  // Registers the image `file` and returns its texture id (0, 1, 2, ...); channels receives its channel
  // count. colorspace (case-insensitive) is how the file's values are encoded: "srgb" (decoded with the IEC
  // 61966-2-1 transfer function), "linear" (used as is) or "auto" (sRGB for integer pixel formats unless the
  // file declares itself linear, linear for float/half formats such as EXR and HDR). The same file (by
  // absolute path) with the same colorspace returns the same id. Throws std::runtime_error naming the
  // file when it is missing or unreadable, the colorspace is unknown, or its conversion cannot be written.
  int add_texture(const std::filesystem::path& file, const std::string& colorspace, int& channels);

  // Filtered lookup (see TextureProvider): periodic wrap, bilinear within a MIP level, trilinear/
  // anisotropic across levels with the filter width `footprint` in uv units. A 1-channel texture asked
  // for 3 channels replicates its channel; channels beyond the texture's are 0. Throws std::out_of_range
  // for an unknown texture id or a channel count other than 1..4. If OIIO fails to read the texture at
  // lookup time (e.g. the cache file was deleted) the result is 0 and the failure is counted in stats().
  void lookup(int texture_id, const Vec2& uv, float footprint, int first_channel, int nchannels,
              float* out) const override;

  int texture_count() const;
  const std::filesystem::path& cache_dir() const;
  // How many textures are resident in memory (the others are looked up through OIIO's tile cache).
  int resident_count() const;
  // Memory held by resident textures plus OIIO's tile cache (ImageCache stat:cache_memory_used), in bytes.
  std::size_t memory_bytes() const;
  // One-line summary: textures, conversions, resident textures and their memory, cache memory, bytes read,
  // failed lookups, cache directory.
  std::string stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ochre
