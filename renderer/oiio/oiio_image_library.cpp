// The module libochre_oiio.so: ImageLibrary (renderer/image/image_library.h) implemented with OpenImageIO.
// The only file of ochre that includes OpenImageIO; it keeps no state of its own.

// fmt first: OIIO bundles its own fmt (exceptions off) under the same include guards.
#include <fmt/format.h>
// OIIO after fmt.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <stdexcept>

#include "renderer/image/image_library.h"

namespace ochre {

namespace {

// Opens `file` for reading; throws with OpenImageIO's message.
std::unique_ptr<OIIO::ImageInput> open_input(const std::string& file,
                                             const OIIO::ImageSpec* config = nullptr) {
  auto input = OIIO::ImageInput::open(file, config);
  if (!input) throw std::runtime_error(OIIO::geterror());
  return input;
}

bool is_floating_point(OIIO::TypeDesc format) {
  return format.basetype == OIIO::TypeDesc::HALF || format.basetype == OIIO::TypeDesc::FLOAT ||
         format.basetype == OIIO::TypeDesc::DOUBLE;
}

// Reads MIP level `level` of subimage 0, channels [0, channels), as `type` into `out`.
void read_level(OIIO::ImageInput& input, int level, int channels, OIIO::TypeDesc type, void* out) {
  if (!input.seek_subimage(0, level)) throw std::runtime_error(fmt::format("no MIP level {}", level));
  if (!input.read_image(0, level, 0, channels, type, out)) throw std::runtime_error(input.geterror());
}

// Throws unless the level the input is at has the size read_header() gave.
void check_size(const OIIO::ImageSpec& spec, const ImageLevelSize& size) {
  if (spec.width != size.width || spec.height != size.height || spec.nchannels < size.channels) {
    throw std::runtime_error(
        fmt::format("the file changed while it was read ({}x{}, {} channels; expected {}x{}, {})", spec.width,
                    spec.height, spec.nchannels, size.width, size.height, size.channels));
  }
}

std::size_t pixel_count(const OIIO::ImageSpec& spec, int channels) {
  return static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
         static_cast<std::size_t>(channels);
}

class OiioTextureCache final : public TextureCache {
 public:
  explicit OiioTextureCache(float max_memory_mb) : system_(OIIO::TextureSystem::create(/*shared=*/false)) {
    if (system_ == nullptr) throw std::runtime_error("cannot create the OpenImageIO TextureSystem");
    // Every channel count is handled by the caller; never let OIIO widen grey on its own.
    system_->attribute("gray_to_rgb", 0);
    system_->attribute("max_memory_MB", max_memory_mb);
  }
  ~OiioTextureCache() override { OIIO::TextureSystem::destroy(system_); }
  OiioTextureCache(const OiioTextureCache&) = delete;
  OiioTextureCache& operator=(const OiioTextureCache&) = delete;

  Handle open(const std::string& file, int& channels) override {
    OIIO::TextureSystem::TextureHandle* handle = system_->get_texture_handle(OIIO::ustring(file));
    OIIO::ImageSpec spec;
    if (handle == nullptr || !system_->good(handle) || !system_->get_imagespec(handle, nullptr, 0, spec)) {
      throw std::runtime_error(system_->geterror());
    }
    channels = spec.nchannels;
    return handle;
  }

  bool lookup(Handle texture, int first_channel, int count, float s, float t, float width,
              float* out) const override {
    OIIO::TextureOpt options;
    options.firstchannel = first_channel;
    options.swrap = OIIO::TextureOpt::WrapPeriodic;
    options.twrap = OIIO::TextureOpt::WrapPeriodic;
    // Bilinear (not OIIO's default smart-bicubic, a non-interpolating B-spline when magnifying), so that
    // a point lookup at a texel centre returns that texel exactly.
    options.interpmode = OIIO::TextureOpt::InterpBilinear;
    OIIO::TextureSystem::Perthread* thread_info = system_->get_perthread_info();
    if (!system_->texture(static_cast<OIIO::TextureSystem::TextureHandle*>(texture), thread_info, options, s,
                          t, width, 0.0f, 0.0f, width, count, out)) {
      (void)system_->geterror();  // do not let errors pile up in OIIO's per-thread buffer
      return false;
    }
    return true;
  }

  std::int64_t memory_used() const override { return cache_statistic("stat:cache_memory_used"); }
  std::int64_t bytes_read() const override { return cache_statistic("stat:bytes_read"); }

 private:
  std::int64_t cache_statistic(const char* name) const {
    long long value = 0;
    system_->imagecache()->getattribute(name, OIIO::TypeDesc::INT64, &value);
    return static_cast<std::int64_t>(value);
  }

  OIIO::TextureSystem* system_;
};

class OiioImageLibrary final : public ImageLibrary {
 public:
  ImageHeader read_header(const std::string& file) const override {
    auto input = open_input(file);
    const OIIO::ImageSpec& spec = input->spec();
    ImageHeader header;
    header.width = spec.width;
    header.height = spec.height;
    header.channels = spec.nchannels;
    header.pixel_type = spec.format.c_str();
    header.floating_point = is_floating_point(spec.format);
    header.tiled = spec.tile_width > 0;
    header.alpha_channel = spec.alpha_channel;
    header.channel_names = spec.channelnames;
    header.colorspace = spec.get_string_attribute("oiio:ColorSpace");
    for (int level = 0; input->seek_subimage(0, level); ++level) {
      const OIIO::ImageSpec& level_spec = input->spec();
      header.levels.push_back({level_spec.width, level_spec.height, level_spec.nchannels});
    }
    (void)input->geterror();  // seeking past the last level leaves a message
    return header;
  }

  std::vector<float> read_float(const std::string& file, int level, const ImageLevelSize& size,
                                bool unassociated_alpha) const override {
    OIIO::ImageSpec config;
    if (unassociated_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = open_input(file, &config);
    if (!input->seek_subimage(0, level)) throw std::runtime_error(fmt::format("no MIP level {}", level));
    check_size(input->spec(), size);
    std::vector<float> pixels(pixel_count(input->spec(), size.channels));
    read_level(*input, level, size.channels, OIIO::TypeDesc::FLOAT, pixels.data());
    return pixels;
  }

  std::vector<std::uint8_t> read_uint8(const std::string& file, const ImageLevelSize& size) const override {
    auto input = open_input(file);
    check_size(input->spec(), size);
    std::vector<std::uint8_t> pixels(pixel_count(input->spec(), size.channels));
    read_level(*input, 0, size.channels, OIIO::TypeDesc::UINT8, pixels.data());
    return pixels;
  }

  void write_uint8(const std::string& format, const std::string& file, int width, int height, int channels,
                   const std::uint8_t* pixels, const ImageAttributes& attributes) const override {
    auto output = OIIO::ImageOutput::create(format);
    if (!output) throw std::runtime_error(fmt::format("OIIO has no {} writer", format));
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    for (const auto& [name, value] : attributes) spec.attribute(name, value);
    if (!output->open(file, spec) || !output->write_image(OIIO::TypeDesc::UINT8, pixels) ||
        !output->close()) {
      throw std::runtime_error(output->geterror());
    }
  }

  void make_texture(const std::vector<float>& pixels, int width, int height,
                    const std::vector<std::string>& channel_names, int alpha_channel,
                    const TextureFileLayout& layout, const std::string& file) const override {
    const int channels = static_cast<int>(channel_names.size());
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = channel_names;
    spec.alpha_channel = alpha_channel;
    if (pixels.size() != pixel_count(spec, channels)) {
      throw std::invalid_argument("make_texture: the pixel count does not match the size");
    }
    // Wraps the caller's pixels (make_texture only reads its source): no copy.
    OIIO::ImageBuf buffer(spec, const_cast<float*>(pixels.data()));

    OIIO::ImageSpec config;
    config.format = layout.half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
    config.tile_width = layout.tile_size;
    config.tile_height = layout.tile_size;
    config.tile_depth = 1;
    for (const auto& [name, value] : layout.attributes) config.attribute(name, value);
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, buffer, file, config)) {
      throw std::runtime_error(OIIO::geterror());
    }
  }

  std::unique_ptr<TextureCache> create_texture_cache(float max_memory_mb) const override {
    return std::make_unique<OiioTextureCache>(max_memory_mb);
  }
};

}  // namespace

}  // namespace ochre

// The module's one exported symbol (renderer/image/image_library.cpp looks it up with dlsym).
extern "C" __attribute__((visibility("default"))) ochre::ImageLibrary* ochre_create_image_library(
    int interface_version) {
  if (interface_version != ochre::kImageLibraryInterfaceVersion) return nullptr;
  return new ochre::OiioImageLibrary();
}
