#pragma once
// Film: per-pixel accumulation of CIE XYZ (and of Y^2 for variance) in exact fixed point.
//
// Floating-point addition is not associative, so a float sum would depend on how the sample
// range is cut between processes. Each sample value is rounded once to a multiple of 2^-40
// and summed in 128-bit integers: integer addition is associative, so any split of the sample
// range, merged, gives the same bits as one run (docs/architecture.md, 'Film'). The rounding error per
// sample (4.5e-13) is far below anything visible; magnitudes are clamped at kMaxSampleMagnitude (1e15),
// and render() counts the samples it clamps (RenderStats::clamped) so that the tools report them.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "spectra/color_types.h"
#include "spectra/sampled_wavelengths.h"

namespace ochre {

// The largest magnitude a sample's value may add to the film; larger ones are clamped to it.
inline constexpr double kMaxSampleMagnitude = 1e15;

struct Vec3f {
  float x = 0, y = 0, z = 0;
};

// The layers a film accumulates besides XYZ; each costs memory per pixel.
struct FilmLayers {
  bool aovs = false;
  int spectral_bins = 0;  // over [spectral_min, spectral_max] nm
  float spectral_min = 360.0f, spectral_max = 830.0f;
  bool stokes = false;
  std::vector<std::string> light_groups;  // XYZ per light group (docs/lights.md, "Light groups")
};

// A light group's name: 1 to 64 letters, digits, '_' or '-' (it names EXR channels, group.<name>.X), and
// at most kMaxLightGroups groups in a film (docs/lights.md, "Light groups").
inline constexpr size_t kMaxLightGroups = 16;
bool is_light_group_name(std::string_view name);

// "film 640x480 (XYZ, AOVs, Stokes, 16 spectral bins)", for messages.
std::string film_description(int width, int height, const FilmLayers& layers);

class Film {
 public:
  // Checks the memory estimate of the film first (renderer/util/memory_budget.h: InputError when it does not
  // fit), then allocates every layer.
  Film(int width, int height, const FilmLayers& layers = {});

  // Accumulator bytes per pixel of a film with these layers.
  static std::size_t bytes_per_pixel(const FilmLayers& layers);

  int width() const { return width_; }
  int height() const { return height_; }

  // Adds one sample's XYZ (already divided by the wavelength pdfs) to pixel (x, y).
  void add_sample(int x, int y, const XYZ& xyz);
  // AOVs (albedo, shading normal, depth at the first hit) cost memory: only when asked for.
  void enable_aovs();
  bool has_aovs() const { return !aovs_.empty(); }
  // Adds one sample's first-hit values (the sample is also added with add_sample).
  void add_aov_sample(int x, int y, const XYZ& albedo, const Vec3f& normal, float depth);
  // Means: albedo (XYZ) and normal over all samples, depth over the samples that hit something.
  XYZ mean_albedo(int x, int y) const;
  Vec3f mean_normal(int x, int y) const;
  float mean_depth(int x, int y) const;

  // Spectral radiance bins (uniform over [lambda_min, lambda_max] nm), only when asked for.
  void enable_spectral(int bins, float lambda_min, float lambda_max);
  int spectral_bins() const { return spectral_bins_; }
  float spectral_bin_centre(int bin) const { return lambda_min_ + (bin + 0.5f) * bin_width_; }
  // Adds one sample's radiance (Stokes component `component`, 0 = S0) at its wavelengths: the
  // Monte-Carlo estimate of each bin's mean.
  void add_spectral_sample(int x, int y, const SampledSpectrum& L, const SampledWavelengths& lambda,
                           int component = 0);
  float mean_spectral(int x, int y, int bin, int component = 0) const;

  // Stokes components S1..S3 (S0 is the XYZ above), XYZ-weighted like S0, and per spectral bin when
  // spectral output is enabled too. Only when asked for.
  void enable_stokes();
  bool has_stokes() const { return stokes_components_ == 4; }
  // Adds one sample's S1, S2, S3 (index 0..2), each XYZ-weighted.
  void add_stokes_sample(int x, int y, const std::array<XYZ, 3>& s123);
  // Mean XYZ-weighted Stokes component c in 1..3.
  XYZ mean_stokes(int x, int y, int c) const;

  // Light groups: XYZ per group (S0 only), whose sum over the groups is the pixel's XYZ up to rounding. With
  // spectral bins (enable_spectral first), each group's XYZ is kept per bin of the sample's wavelength, so
  // that a new emission spectrum can weigh each bin (docs/lights.md, "Relighting").
  void enable_light_groups(const std::vector<std::string>& names);
  const std::vector<std::string>& light_groups() const { return light_groups_; }
  // 1, or the spectral bins when the groups are kept per bin.
  int group_bins() const { return group_bins_; }
  // The group bin of a wavelength: its spectral bin, wavelengths outside the range in the first or last.
  int group_bin(float lambda_nm) const;
  // Adds one sample's XYZ of group `group` from wavelengths of bin `bin` (the sample's total is added with
  // add_sample).
  void add_group_sample(int x, int y, size_t group, int bin, const XYZ& xyz);
  // Mean XYZ of group `group` over the pixel's samples: of every bin, or of bin `bin`.
  XYZ mean_group(int x, int y, size_t group) const;
  XYZ mean_group(int x, int y, size_t group, int bin) const;

  // Adds the sums of another film with the same layers over the same pixels (a disjoint sample range),
  // or, with an offset, over the pixels [x0, x0 + other.width()) x [y0, y0 + other.height()) of this
  // film (a tile of a region split; the tile must fit).
  void merge(const Film& other, int x0 = 0, int y0 = 0);
  FilmLayers layers() const;

  // The exact sums, for partial-render files (renderer/output/partial_sums.h): a list of named accumulators
  // that depends on the layers ("X", "Y", "Z", "Y2", "count", then "albedo.X", ..., "S1.X", ...,
  // "S0.bin0", ...), each one integer per pixel (pixel = y * width + x).
  std::vector<std::string> accumulator_names() const;
  __int128 accumulator(size_t index, size_t pixel) const;
  void set_accumulator(size_t index, size_t pixel, __int128 value);

  uint64_t sample_count(int x, int y) const { return pixels_[index(x, y)].count; }
  // Mean XYZ of the pixel (0 with no samples).
  XYZ mean(int x, int y) const;
  // Sample variance of Y over the pixel's samples (0 with fewer than 2 samples).
  double variance_y(int x, int y) const;

 private:
  struct AovPixel {
    __int128 albedo[3] = {0, 0, 0};
    __int128 normal[3] = {0, 0, 0};
    __int128 depth = 0;
    uint64_t hits = 0;
  };
  struct Pixel {
    __int128 xyz[3] = {0, 0, 0};
    __int128 y2 = 0;
    uint64_t count = 0;
  };
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }
  // Accumulator `index` of a pixel: a 128-bit sum or a 64-bit count (exactly one is set).
  struct AccumulatorRef {
    __int128* sum = nullptr;
    uint64_t* count = nullptr;
  };
  AccumulatorRef accumulator_ref(size_t index, size_t pixel);

  int width_, height_;
  std::vector<Pixel> pixels_;
  std::vector<AovPixel> aovs_;
  void allocate_spectral();

  std::vector<__int128> spectral_;  // per pixel: components x bins
  int spectral_bins_ = 0;
  int stokes_components_ = 1;     // 4 with Stokes output
  std::vector<__int128> stokes_;  // per pixel: S1..S3 x XYZ
  std::vector<std::string> light_groups_;
  std::vector<__int128> groups_;  // per pixel: groups x group bins x XYZ
  int group_bins_ = 1;
  float lambda_min_ = 0.0f, bin_width_ = 0.0f;
};

}  // namespace ochre
