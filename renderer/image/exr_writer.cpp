#include "renderer/image/exr_writer.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include <set>

#include "renderer/util/atomic_file.h"
#include "renderer/util/image_error.h"

namespace ochre {

namespace fs = std::filesystem;

Chromaticities rec709_chromaticities() {
  // ITU-R BT.709-6, table "Derivation of primary colour signals"; D65 white.
  return {{0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, {0.3127f, 0.3290f}};
}

Chromaticities acescg_chromaticities() {
  // ACES AP1 primaries and ACES white point (Academy S-2014-004, ACEScg).
  return {{0.713f, 0.293f}, {0.165f, 0.830f}, {0.128f, 0.044f}, {0.32168f, 0.33767f}};
}

const std::vector<float>* ExrImage::find_channel(std::string_view name) const {
  for (const auto& [channel_name, values] : channels) {
    if (channel_name == name) return &values;
  }
  return nullptr;
}

namespace {

struct CompressionName {
  std::string_view name;
  ExrCompression value;
};

constexpr CompressionName compression_names[] = {
    {"none", ExrCompression::none}, {"rle", ExrCompression::rle},   {"zips", ExrCompression::zips},
    {"zip", ExrCompression::zip},   {"piz", ExrCompression::piz},   {"pxr24", ExrCompression::pxr24},
    {"b44", ExrCompression::b44},   {"b44a", ExrCompression::b44a}, {"dwaa", ExrCompression::dwaa},
    {"dwab", ExrCompression::dwab},
};

Imf::Compression to_imf(ExrCompression compression) {
  switch (compression) {
    case ExrCompression::none:
      return Imf::NO_COMPRESSION;
    case ExrCompression::rle:
      return Imf::RLE_COMPRESSION;
    case ExrCompression::zips:
      return Imf::ZIPS_COMPRESSION;
    case ExrCompression::zip:
      return Imf::ZIP_COMPRESSION;
    case ExrCompression::piz:
      return Imf::PIZ_COMPRESSION;
    case ExrCompression::pxr24:
      return Imf::PXR24_COMPRESSION;
    case ExrCompression::b44:
      return Imf::B44_COMPRESSION;
    case ExrCompression::b44a:
      return Imf::B44A_COMPRESSION;
    case ExrCompression::dwaa:
      return Imf::DWAA_COMPRESSION;
    case ExrCompression::dwab:
      return Imf::DWAB_COMPRESSION;
  }
  return Imf::ZIP_COMPRESSION;
}

// Rejects what OpenEXR would reject later with a less helpful message (or silently accept: a duplicate
// channel name would overwrite the first one).
void check_image(const fs::path& path, const ExrImage& image) {
  const std::string file = path.string();
  if (image.width <= 0 || image.height <= 0) {
    throw ImageError(fmt::format("cannot write {}: invalid size {}x{}", file, image.width, image.height));
  }
  if (image.channels.empty())
    throw ImageError(fmt::format("cannot write {}: the image has no channel", file));
  const size_t pixel_count = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  std::set<std::string_view> names;
  for (const auto& [name, values] : image.channels) {
    if (name.empty()) throw ImageError(fmt::format("cannot write {}: a channel has an empty name", file));
    if (!names.insert(name).second) {
      throw ImageError(fmt::format("cannot write {}: channel '{}' appears twice", file, name));
    }
    if (values.size() != pixel_count) {
      throw ImageError(fmt::format("cannot write {}: channel '{}' has {} values, expected {} ({}x{})", file,
                                   name, values.size(), pixel_count, image.width, image.height));
    }
  }
}

Imf::Header make_header(const fs::path& path, const ExrImage& image, ExrCompression compression, bool half) {
  Imf::Header header(image.width, image.height);
  header.compression() = to_imf(compression);
  const Imf::PixelType file_type = half ? Imf::HALF : Imf::FLOAT;
  for (const auto& channel : image.channels) header.channels().insert(channel.first, Imf::Channel(file_type));
  if (image.chromaticities) {
    const Chromaticities& c = *image.chromaticities;
    Imf::addChromaticities(
        header, Imf::Chromaticities(Imath::V2f(c.red[0], c.red[1]), Imath::V2f(c.green[0], c.green[1]),
                                    Imath::V2f(c.blue[0], c.blue[1]), Imath::V2f(c.white[0], c.white[1])));
  }
  for (const auto& [name, value] : image.string_attributes) {
    if (name.empty() || header.find(name) != header.end()) {
      throw ImageError(fmt::format("cannot write {}: attribute name '{}' is reserved by the EXR header",
                                   path.string(), name));
    }
    header.insert(name, Imf::StringAttribute(value));
  }
  return header;
}

}  // namespace

ExrCompression parse_exr_compression(std::string_view name) {
  std::string accepted;
  for (const auto& entry : compression_names) {
    if (entry.name == name) return entry.value;
    accepted += accepted.empty() ? "" : ", ";
    accepted += entry.name;
  }
  throw ImageError(fmt::format("unknown EXR compression '{}' (expected one of: {})", name, accepted));
}

void write_exr(const fs::path& path, const ExrImage& image, ExrCompression compression, bool half) {
  AtomicOutput output(path);
  write_exr(output, image, compression, half);
  output.commit();
}

void write_exr(AtomicOutput& output, const ExrImage& image, ExrCompression compression, bool half) {
  const fs::path& path = output.final_path();
  check_image(path, image);
  const Imf::Header header = make_header(path, image, compression, half);

  // OpenEXR does not convert float to half on output: half files get a half copy of each channel.
  std::vector<std::vector<Imath::half>> half_channels;
  if (half) {
    half_channels.reserve(image.channels.size());
    for (const auto& channel : image.channels)
      half_channels.emplace_back(channel.second.begin(), channel.second.end());
  }
  Imf::FrameBuffer frame;
  for (size_t i = 0; i < image.channels.size(); ++i) {
    const auto& [name, values] = image.channels[i];
    const char* base = half ? reinterpret_cast<const char*>(half_channels[i].data())
                            : reinterpret_cast<const char*>(values.data());
    const size_t pixel_size = half ? sizeof(Imath::half) : sizeof(float);
    frame.insert(name, Imf::Slice(half ? Imf::HALF : Imf::FLOAT, const_cast<char*>(base), pixel_size,
                                  pixel_size * static_cast<size_t>(image.width)));
  }

  try {
    Imf::OutputFile file(output.temp_path().c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  } catch (const std::exception& error) {
    throw ImageError(fmt::format("cannot write {}: {}", path.string(), error.what()));
  }
}

}  // namespace ochre
