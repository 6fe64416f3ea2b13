#include "renderer/texture/texture_system.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "renderer/image/image_library.h"
#include "renderer/texture/mip_pyramid.h"
#include "renderer/texture/periodic_texture_coordinate.h"
#include "renderer/util/ascii_case.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/fnv1a.h"
#include "renderer/util/memory_budget.h"
#include "spectra/color_space.h"
#include "spectra/input_file.h"
#include "spectra/non_finite.h"

namespace ochre {

namespace fs = std::filesystem;

namespace {

// Bump when the conversion changes, so old cache files are not reused.
constexpr int kCacheFormatVersion = 1;

enum class Encoding { srgb, linear };

const char* encoding_name(Encoding encoding) {
  return encoding == Encoding::srgb ? "srgb" : "linear";
}

// ------------------------------------------------------------------------------------ cache directory

fs::path env_path(const char* name) {
  const char* value = std::getenv(name);
  return (value != nullptr && *value != '\0') ? fs::path(value) : fs::path();
}

fs::path temp_cache_dir() {
  std::error_code error;
  const fs::path temp = fs::temp_directory_path(error);
  return (error ? fs::path("/tmp") : temp) / "ochre-textures";
}

// Creates dir if needed and checks that a file can be created in it (access(2) is not enough: root
// passes it on read-only filesystems).
bool make_writable_directory(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir, error)) return false;
  const fs::path probe = dir / fmt::format(".ochre-write-probe-{}", static_cast<long>(::getpid()));
  bool writable = false;
  {
    std::ofstream stream(probe);
    writable = stream.good() && (stream << "probe").good();
  }
  fs::remove(probe, error);
  return writable;
}

// ------------------------------------------------------------------------------------ source files

struct SourceInfo {
  fs::path path;  // absolute, normalized
  ImageHeader header;
  bool tiled_and_mipmapped = false;
};

[[noreturn]] void throw_unreadable(const fs::path& file, const std::string& why) {
  throw std::runtime_error(fmt::format("cannot read texture {}: {}", file.string(), why));
}

// Reads the header of `file`; throws naming the file when it is missing or not an image OIIO can read.
SourceInfo open_source(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error)) throw_unreadable(file, "the file does not exist");
  check_regular_input(file, kTextureInput);  // a FIFO or a device is refused before OIIO opens it
  SourceInfo info;
  info.path = fs::weakly_canonical(fs::absolute(file), error);
  if (error) info.path = fs::absolute(file).lexically_normal();
  try {
    info.header = image_library().read_header(info.path.string());
  } catch (const std::runtime_error& e) {
    throw_unreadable(file, e.what());
  }
  if (info.header.channels < 1 || info.header.width < 1 || info.header.height < 1) {
    throw_unreadable(file, "the image is empty");
  }
  info.tiled_and_mipmapped = info.header.tiled && info.header.mipmapped();
  return info;
}

// "auto": integer pixels are display-encoded (sRGB) unless the file says it is linear; float/half
// pixels (EXR, HDR) are scene-linear.
Encoding resolve_encoding(const SourceInfo& source, const std::string& colorspace) {
  if (equals_ignoring_case(colorspace, "srgb")) return Encoding::srgb;
  if (equals_ignoring_case(colorspace, "linear")) return Encoding::linear;
  if (!equals_ignoring_case(colorspace, "auto")) {
    throw std::runtime_error(
        fmt::format("texture {}: unknown colorspace \"{}\" (expected auto, srgb or linear)",
                    source.path.string(), colorspace));
  }
  const std::string& declared = source.header.colorspace;
  const bool declared_linear =
      equals_ignoring_case(declared, "linear") || equals_ignoring_case(declared, "scene_linear");
  return (!source.header.floating_point && !declared_linear) ? Encoding::srgb : Encoding::linear;
}

// Cache file name: source stem + hash of (absolute path, size, mtime, encoding, format version), so an
// edited source file gets a new name and is converted again.
fs::path cache_file_for(const fs::path& cache_dir, const SourceInfo& source, Encoding encoding) {
  std::error_code error;
  const auto size = fs::file_size(source.path, error);
  const auto mtime = fs::last_write_time(source.path, error).time_since_epoch().count();
  const std::string key = fmt::format("v{}|{}|{}|{}|{}", kCacheFormatVersion, source.path.string(), size,
                                      static_cast<long long>(mtime), encoding_name(encoding));
  const std::string stem = source.path.stem().string().substr(0, 64);
  return cache_dir / fmt::format("{}-{:016x}.exr", stem, fnv1a64(key));
}

// ------------------------------------------------------------------------------------ conversion

// Reads the first subimage of the source as float, in [0, 1] for integer formats. Alpha is kept
// unassociated (as stored in PNG), so colour and mask channels are filtered as they were painted.
std::vector<float> read_as_float(const SourceInfo& source) {
  // The float pixels, then MakeTx's copy of them and its MIP levels (a third more).
  const ImageHeader& header = source.header;
  check_memory_estimate(
      static_cast<double>(header.width) * header.height * header.channels * sizeof(float) * (2.0 + 1.0 / 3.0),
      fmt::format("converting texture {} ({}x{}, {} channels)", source.path.string(), header.width,
                  header.height, header.channels));
  try {
    return image_library().read_float(source.path.string(), 0, {header.width, header.height, header.channels},
                                      /*unassociated_alpha=*/true);
  } catch (const std::runtime_error& e) {
    throw_unreadable(source.path, e.what());
  }
}

void decode_srgb(std::vector<float>& pixels, const ImageHeader& header) {
  const std::size_t count = static_cast<std::size_t>(header.width) * header.height;
  for (std::size_t pixel = 0; pixel < count; ++pixel) {
    for (int channel = 0; channel < header.channels; ++channel) {
      if (channel == header.alpha_channel) continue;  // coverage, not colour
      float& value = pixels[pixel * header.channels + channel];
      value = srgb_decode(value);  // IEC 61966-2-1 transfer function
    }
  }
}

// The source's channel names, or R, G, B, A, ... when the file does not give one per channel.
std::vector<std::string> channel_names_of(const ImageHeader& header) {
  if (static_cast<int>(header.channel_names.size()) == header.channels) return header.channel_names;
  static const char* const kDefault[] = {"R", "G", "B", "A"};
  std::vector<std::string> names;
  for (int channel = 0; channel < header.channels; ++channel) {
    names.push_back(channel < 4 ? kDefault[channel] : fmt::format("channel{}", channel));
  }
  return names;
}

// Writes a tiled, MIP-mapped OpenEXR texture of the linear pixels of `source` to `target` (temporary
// name, then rename: a concurrent render never sees a half-written file). Integer sources become half
// (11-bit mantissa: finer than 8-bit sRGB steps everywhere), float sources stay float.
void convert_to_texture(const SourceInfo& source, Encoding encoding, const fs::path& target) {
  const ImageHeader& header = source.header;
  std::vector<float> pixels = read_as_float(source);
  if (encoding == Encoding::srgb) decode_srgb(pixels, header);

  TextureFileLayout layout;
  layout.half = header.pixel_type != "float" && header.pixel_type != "double";
  layout.tile_size = 64;
  layout.attributes = {{"compression", "zip"},
                       {"wrapmodes", "periodic,periodic"},
                       {"oiio:ColorSpace", "Linear"},
                       {"ochre:source", source.path.string()},
                       {"ochre:source_encoding", encoding_name(encoding)},
                       // the temporary name has no .exr extension
                       {"maketx:fileformatname", "openexr"}};

  AtomicOutput output(target);
  try {
    image_library().make_texture(pixels, header.width, header.height, channel_names_of(header),
                                 header.alpha_channel, layout, output.temp_path().string());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(
        fmt::format("cannot convert texture {} to {}: {}", source.path.string(), target.string(), e.what()));
  }
  output.commit();
}

// OpenImageIO 2.4 defaults to a 256 MB tile cache; photogrammetry walls carry several 8k textures.
constexpr float kTileCacheMegabytes = 1024.0f;

}  // namespace

fs::path default_texture_cache_dir() {
  if (fs::path dir = env_path("OCHRE_CACHE_DIR"); !dir.empty()) return dir;
  if (fs::path dir = env_path("XDG_CACHE_HOME"); !dir.empty()) return dir / "ochre" / "textures";
  if (fs::path dir = env_path("HOME"); !dir.empty()) return dir / ".cache" / "ochre" / "textures";
  return temp_cache_dir();
}

// ------------------------------------------------------------------------------------ provider

struct OiioTextureProvider::Impl {
  struct Texture {
    TextureCache::Handle handle = nullptr;
    int channels = 0;
    fs::path file;  // what the TextureSystem reads (cache file or the source itself)
    std::unique_ptr<const MipPyramid> resident;  // its MIP levels in memory, when they fit the budget
  };

  fs::path cache_dir;
  std::string cache_note;  // why the requested cache directory was not used, if it was not
  // Created with the first texture: a scene without textures never loads the image library.
  std::unique_ptr<TextureCache> cache;
  std::vector<Texture> textures;
  std::unordered_map<std::string, int> ids;  // "<absolute path>|<encoding>" -> id
  std::mutex add_mutex;
  std::size_t resident_budget = 0, resident_bytes = 0;
  int conversions = 0, cache_hits = 0, used_directly = 0;
  mutable std::atomic<std::uint64_t> failed_lookups{0};

  // Returns the file the TextureSystem should read for source/encoding, converting it if needed.
  TextureCache& tile_cache() {
    if (!cache) cache = image_library().create_texture_cache(kTileCacheMegabytes);
    return *cache;
  }

  fs::path texture_file_for(const SourceInfo& source, Encoding encoding) {
    if (encoding == Encoding::linear && source.tiled_and_mipmapped) {
      ++used_directly;  // already a linear MIP-mapped texture (e.g. made by maketx)
      return source.path;
    }
    const fs::path target = cache_file_for(cache_dir, source, encoding);
    std::error_code error;
    if (fs::is_regular_file(target, error)) {
      ++cache_hits;
      return target;
    }
    convert_to_texture(source, encoding, target);
    ++conversions;
    return target;
  }
};

OiioTextureProvider::OiioTextureProvider(fs::path cache_dir, std::size_t resident_budget_bytes)
    : impl_(std::make_unique<Impl>()) {
  impl_->resident_budget = resident_budget_bytes;
  impl_->cache_dir = cache_dir.empty() ? default_texture_cache_dir() : std::move(cache_dir);
  if (!make_writable_directory(impl_->cache_dir)) {
    const fs::path requested = impl_->cache_dir;
    const fs::path fallback = temp_cache_dir();
    if (!make_writable_directory(fallback)) {
      throw std::runtime_error(
          fmt::format("cannot create a texture cache directory: neither {} nor {} is writable",
                      requested.string(), fallback.string()));
    }
    impl_->cache_dir = fallback;
    impl_->cache_note = fmt::format(" (requested {} is not writable)", requested.string());
  }
}

OiioTextureProvider::~OiioTextureProvider() = default;

int OiioTextureProvider::add_texture(const fs::path& file, const std::string& colorspace, int& channels) {
  std::lock_guard lock(impl_->add_mutex);
  const SourceInfo source = open_source(file);
  const Encoding encoding = resolve_encoding(source, colorspace);
  const std::string key = fmt::format("{}|{}", source.path.string(), encoding_name(encoding));
  if (auto found = impl_->ids.find(key); found != impl_->ids.end()) {
    channels = impl_->textures[found->second].channels;
    return found->second;
  }

  Impl::Texture texture;
  texture.file = impl_->texture_file_for(source, encoding);
  try {
    texture.handle = impl_->tile_cache().open(texture.file.string(), texture.channels);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("cannot read texture {} (converted file {}): {}",
                                         source.path.string(), texture.file.string(), e.what()));
  }
  const std::size_t bytes = MipPyramid::file_bytes(texture.file);
  if (bytes > 0 && impl_->resident_bytes + bytes <= impl_->resident_budget) {
    texture.resident = std::make_unique<const MipPyramid>(MipPyramid::load(texture.file));
    impl_->resident_bytes += texture.resident->memory_bytes();
  }

  const int id = static_cast<int>(impl_->textures.size());
  impl_->textures.push_back(std::move(texture));
  impl_->ids.emplace(key, id);
  channels = impl_->textures.back().channels;
  return id;
}

void OiioTextureProvider::lookup(int texture_id, const Vec2& uv, float footprint, int first_channel,
                                 int nchannels, float* out) const {
  if (texture_id < 0 || texture_id >= static_cast<int>(impl_->textures.size())) {
    throw std::out_of_range(fmt::format("texture lookup: unknown texture id {}", texture_id));
  }
  if (nchannels < 1 || nchannels > 4 || first_channel < 0) {
    throw std::out_of_range(
        fmt::format("texture lookup: invalid channels {}..{}", first_channel, first_channel + nchannels - 1));
  }
  const Impl::Texture& texture = impl_->textures[static_cast<std::size_t>(texture_id)];
  std::fill(out, out + nchannels, 0.0f);

  // A grey texture read as colour replicates its channel; channels past the last one stay 0.
  const bool replicate_grey = texture.channels == 1 && first_channel == 0;
  const int fetched = replicate_grey ? 1 : std::clamp(texture.channels - first_channel, 0, nchannels);
  if (fetched == 0) return;

  // NaN or infinite coordinates read nothing (0); huge ones wrap to 0 and an infinite footprint is the
  // largest float, both without any float -> int conversion out of range (periodic_texture_coordinate.h).
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return;
  const float s = periodic_texture_coordinate(uv.x), v = periodic_texture_coordinate(uv.y);
  // Isotropic filter footprint: ds/dx = dt/dy = footprint. t runs down the image, v up: t = 1 - v.
  const float width = finite_or_limit(std::fabs(footprint));
  if (texture.resident) {
    texture.resident->lookup(s, 1.0f - v, width, first_channel, fetched, out);
    if (replicate_grey) std::fill(out + 1, out + nchannels, out[0]);
    return;
  }

  // Bilinear within a level (a point lookup at a texel centre returns that texel exactly), periodic wrap.
  if (!impl_->cache->lookup(texture.handle, first_channel, fetched, s, 1.0f - v, width, out)) {
    impl_->failed_lookups.fetch_add(1, std::memory_order_relaxed);
    std::fill(out, out + nchannels, 0.0f);
    return;
  }
  if (replicate_grey) std::fill(out + 1, out + nchannels, out[0]);
}

int OiioTextureProvider::texture_count() const {
  return static_cast<int>(impl_->textures.size());
}

const fs::path& OiioTextureProvider::cache_dir() const {
  return impl_->cache_dir;
}

int OiioTextureProvider::resident_count() const {
  return static_cast<int>(std::count_if(impl_->textures.begin(), impl_->textures.end(),
                                        [](const Impl::Texture& t) { return t.resident != nullptr; }));
}

std::size_t OiioTextureProvider::memory_bytes() const {
  const std::int64_t bytes = impl_->cache ? impl_->cache->memory_used() : 0;
  return static_cast<std::size_t>(std::max<std::int64_t>(0, bytes)) + impl_->resident_bytes;
}

std::string OiioTextureProvider::stats() const {
  const std::int64_t bytes_read = impl_->cache ? impl_->cache->bytes_read() : 0;
  constexpr double kMiB = 1024.0 * 1024.0;
  return fmt::format(
      "textures: {} ({} converted, {} from cache, {} used as is; {} resident, {:.1f} MiB); tile cache "
      "{:.1f} MiB, read {:.1f} MiB; failed lookups {}; cache {}{}",
      impl_->textures.size(), impl_->conversions, impl_->cache_hits, impl_->used_directly, resident_count(),
      static_cast<double>(impl_->resident_bytes) / kMiB,
      static_cast<double>(memory_bytes() - impl_->resident_bytes) / kMiB,
      static_cast<double>(bytes_read) / kMiB, impl_->failed_lookups.load(std::memory_order_relaxed),
      impl_->cache_dir.string(), impl_->cache_note);
}

}  // namespace ochre
