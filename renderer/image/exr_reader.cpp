#include "renderer/image/exr_reader.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include "renderer/image/exr_input_stream.h"
#include "renderer/util/image_error.h"
#include "renderer/util/memory_budget.h"
#include "spectra/input_error.h"
#include "spectra/input_file.h"

namespace ochre {

namespace {

void read_string_attributes(const Imf::Header& header, ExrImage& image) {
  for (auto it = header.begin(); it != header.end(); ++it) {
    if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) {
      image.string_attributes.emplace(it.name(), text->value());
    }
  }
}

void read_chromaticities(const Imf::Header& header, ExrImage& image) {
  if (!Imf::hasChromaticities(header)) return;
  const Imf::Chromaticities& c = Imf::chromaticities(header);
  image.chromaticities = Chromaticities{
      {c.red.x, c.red.y}, {c.green.x, c.green.y}, {c.blue.x, c.blue.y}, {c.white.x, c.white.y}};
}

}  // namespace

ExrImage read_exr(const std::filesystem::path& path) {
  const std::string file_name = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw ImageError(fmt::format("cannot read {}: no such file", file_name));
  }
  InputFile input = InputFile::open(path, kImageFileInput);
  try {
    InputFileIStream stream(input);
    Imf::InputFile file(stream);
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();

    ExrImage image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    const size_t pixel_count = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    double channel_count = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) ++channel_count;
    check_memory_estimate(static_cast<double>(pixel_count) * channel_count * sizeof(float),
                          fmt::format("reading {} ({}x{}, {:.0f} channels)", file_name, image.width,
                                      image.height, channel_count));

    // Channels come out in the file's order (sorted by name); every type is converted to float.
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
      if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
        throw ImageError(
            fmt::format("cannot read {}: channel '{}' is subsampled (not supported)", file_name, it.name()));
      }
      image.channels.emplace_back(it.name(), std::vector<float>(pixel_count));
    }
    Imf::FrameBuffer frame;
    for (auto& [name, values] : image.channels) {
      frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);

    read_string_attributes(header, image);
    read_chromaticities(header, image);
    return image;
  } catch (const ImageError&) {
    throw;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    throw ImageError(fmt::format("cannot read {}: {}", file_name, error.what()));
  }
}

}  // namespace ochre
