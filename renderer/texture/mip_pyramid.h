#pragma once
// MipPyramid: a texture's MIP levels held in memory as float, with the lookups of the texture node
// (periodic wrap, bilinear within a level, trilinear across levels for an isotropic footprint).
//
// Why: OpenImageIO's TextureSystem pages tiles through a cache and resolves the texture, tile and filter
// on every call, which cost ~300 ns per lookup and 14 % of the default scene's render time. A texture
// that fits in memory is read once, level by level, from the MIP-mapped file OIIO's make_texture wrote
// (so the levels are filtered exactly as for the TextureSystem), and looked up directly: a bilinear
// lookup reads four texels in two rows of one level.
//
// Conventions (those of OiioTextureProvider): level 0 is the full image, row 0 its TOP row; the lookup
// takes s = u and t = 1 - v (uv have v up); texel centres sit at ((i + 0.5) / width, (j + 0.5) / height),
// where a point lookup returns the texel exactly. The level of a footprint w (uv units) is
// log2(w x max(width, height)) of level 0, blended linearly between the two nearest levels; w = 0 or a
// footprint under one texel reads level 0.

#include <cstddef>
#include <filesystem>
#include <vector>

namespace ochre {

class MipPyramid {
 public:
  struct Level {
    int width = 0, height = 0;
    std::vector<float> texels;  // width * height * channels, row-major, top row first
  };

  MipPyramid() = default;
  // levels[0] is the full image, each further one the next smaller MIP level; every level has
  // `channels` (1..4) channels. Throws std::invalid_argument on inconsistent sizes.
  MipPyramid(std::vector<Level> levels, int channels);

  // Bytes the MIP levels of the image file `file` would take as float, or 0 when it cannot be read.
  static std::size_t file_bytes(const std::filesystem::path& file);
  // Reads every MIP level of `file` (subimage 0) as float. Throws std::runtime_error naming the file.
  static MipPyramid load(const std::filesystem::path& file);

  int channels() const { return channels_; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  const Level& level(int i) const { return levels_[static_cast<std::size_t>(i)]; }
  std::size_t memory_bytes() const;

  // Filtered lookup of channels [first_channel, first_channel + n) at (s, t) (t down the image) with the
  // isotropic footprint `footprint` (s/t units), written to out. The caller checks the channel range.
  // NaN or infinite s or t give 0; |s|, |t| >= 2^23 read as 0 (periodic_texture_coordinate.h); a NaN
  // footprint reads level 0, an infinite one the last level.
  void lookup(float s, float t, float footprint, int first_channel, int n, float* out) const;

 private:
  void bilinear(const Level& level, float s, float t, int first_channel, int n, float weight,
                float* out) const;

  std::vector<Level> levels_;
  int channels_ = 0;
  float level0_size_ = 0.0f;  // max(width, height) of level 0
};

}  // namespace ochre
