// Fuzz target: environment maps (renderer/lights/environment_map.h, renderer/lights/environment_light.h) from
// HDR and OpenEXR bytes. The input is written as map.exr when it starts with the OpenEXR magic number, else
// as map.hdr, read by EnvironmentMap::load (OpenImageIO), turned into an environment light and sampled and
// looked up in a few directions.
//
// Bounded work, skipped before loading (see docs/validation.md): images whose header declares more than
// 2^20 values (texels x channels; a 30-byte header may declare gigabytes of pixels) in the image or in one
// tile (OpenImageIO allocates a whole tile, however small the image), and OpenEXR files
// with a header attribute larger than the file (OpenEXR 3.1 allocates the declared size, up to 2 GB,
// before it finds the file too short). Expected errors:
// the std::runtime_error that EnvironmentMap::load documents.

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fuzz_support.h"
#include "renderer/lights/environment_light.h"
#include "spectra/sampled_wavelengths.h"

namespace {

constexpr long long kMaxValues = 1 << 20;

// Whether every attribute of every header of an OpenEXR file (name\0 type\0 int32 size, value) fits in
// the file. The headers follow the 8-byte magic and version; each ends with an empty name, the list of
// a multi-part file with one more.
bool exr_attributes_fit(std::string_view bytes) {
  size_t pos = 8;
  bool header_ended = false;
  while (pos < bytes.size()) {
    const size_t name_end = bytes.find('\0', pos);
    if (name_end == std::string_view::npos) return true;  // truncated: OpenEXR reports it
    if (name_end == pos) {                                // an empty name ends a header
      if (header_ended) return true;                      // ... and the empty header, the list
      header_ended = true;
      ++pos;
      continue;
    }
    header_ended = false;
    const size_t type_end = bytes.find('\0', name_end + 1);
    if (type_end == std::string_view::npos || type_end + 5 > bytes.size()) return true;
    uint32_t size = 0;
    std::memcpy(&size, bytes.data() + type_end + 1, 4);  // little-endian, as the format
    pos = type_end + 5;
    if (size > bytes.size() - pos) return false;
    pos += size;
  }
  return true;
}

bool declares_few_values(const std::filesystem::path& file) {
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) {
    OIIO::geterror();  // clear the message, or OIIO keeps it per thread
    return true;       // EnvironmentMap::load reports it
  }
  const OIIO::ImageSpec& spec = input->spec();
  const long long channels = spec.nchannels,
                  tile = static_cast<long long>(spec.tile_width) * spec.tile_height;
  return static_cast<long long>(spec.width) * spec.height * std::max(spec.depth, 1) * channels <=
             kMaxValues &&
         tile * std::max(spec.tile_depth, 1) * channels <= kMaxValues;
}

// Texels near the float limit may give infinite radiance or power; NaN is never right.
void check_not_nan(float value, const char* what) {
  if (std::isnan(value)) {
    std::fprintf(stderr, "ochre fuzz: FINDING: %s is %f\n", what, value);
    std::abort();
  }
}

void exercise(const std::shared_ptr<const ochre::EnvironmentMap>& map) {
  const ochre::EnvironmentLight light(map, /*scene_radius=*/1.0f, /*scale=*/1.0f, /*rotation_degrees=*/30.0f);
  check_not_nan(light.power(), "the light's power");
  const auto lambda = ochre::SampledWavelengths::sample_visible(0.29f);
  for (const ochre::Vec2& u :
       {ochre::Vec2{0.1f, 0.2f}, ochre::Vec2{0.5f, 0.5f}, ochre::Vec2{0.999f, 0.001f}}) {
    if (const auto s = light.sample({0, 0, 0}, u, lambda)) {
      check_not_nan(s->pdf, "a sample's pdf");
      for (int i = 0; i < ochre::kSpectrumSamples; ++i) check_not_nan(s->radiance[i], "a sample's radiance");
    }
  }
  for (const ochre::Vec3& d : {ochre::Vec3{0, 1, 0}, ochre::Vec3{0, -1, 0}, ochre::Vec3{0.6f, 0, -0.8f}}) {
    float pdf = 0.0f;
    const ochre::SampledSpectrum radiance = light.radiance(d, lambda, &pdf);
    check_not_nan(pdf, "a direction's pdf");
    for (int i = 0; i < ochre::kSpectrumSamples; ++i) check_not_nan(radiance[i], "a direction's radiance");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const char kExrMagic[] = {0x76, 0x2f, 0x31, 0x01};
  const std::string_view bytes = ochre::fuzz::as_text(data, size);
  const bool exr = bytes.substr(0, 4) == std::string_view(kExrMagic, 4);
  const std::filesystem::path file = ochre::fuzz::write_workspace_file(exr ? "map.exr" : "map.hdr", bytes);
  if ((exr && !exr_attributes_fit(bytes)) || !declares_few_values(file)) return 0;
  ochre::fuzz::expect_only_input_errors(
      [&] { exercise(std::make_shared<const ochre::EnvironmentMap>(ochre::EnvironmentMap::load(file))); },
      /*parser_errors=*/true);
  return 0;
}
